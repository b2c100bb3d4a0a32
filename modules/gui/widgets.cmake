# camwb_gui_widgets: the VTK 3D view (own Qt6 QOpenGLWidget bridge, Debian's VTK Qt module is
# Qt5-only) and the NC editor (QScintilla). VTK and QScintilla stay private: no public header
# includes them. Included from modules/gui/CMakeLists.txt.
set(_camwb_gui_widgets_dir ${CMAKE_CURRENT_LIST_DIR})
add_library(camwb_gui_widgets STATIC
  ${_camwb_gui_widgets_dir}/view3d/detail/ToolpathScene.h
  ${_camwb_gui_widgets_dir}/view3d/ToolpathScene.cpp
  ${_camwb_gui_widgets_dir}/view3d/VtkOpenGLWidget.h
  ${_camwb_gui_widgets_dir}/view3d/VtkOpenGLWidget.cpp
  ${_camwb_gui_widgets_dir}/view3d/detail/ModelActors.h
  ${_camwb_gui_widgets_dir}/view3d/ModelActors.cpp
  ${_camwb_gui_widgets_dir}/view3d/detail/SetupActors.h
  ${_camwb_gui_widgets_dir}/view3d/SetupActors.cpp
  ${_camwb_gui_widgets_dir}/view3d/TaskOverlay.h
  ${_camwb_gui_widgets_dir}/view3d/TaskOverlay.cpp
  ${_camwb_gui_widgets_dir}/view3d/View3D.h
  ${_camwb_gui_widgets_dir}/view3d/View3D.cpp
  ${_camwb_gui_widgets_dir}/sim/SimOverlay.h
  ${_camwb_gui_widgets_dir}/sim/SimOverlay.cpp
  ${_camwb_gui_widgets_dir}/view3d/detail/MachineFrameActors.h
  ${_camwb_gui_widgets_dir}/view3d/MachineFrameActors.cpp
  ${_camwb_gui_widgets_dir}/sim/SimChart.h
  ${_camwb_gui_widgets_dir}/sim/SimChart.cpp
  ${_camwb_gui_widgets_dir}/editor/NcStyles.h
  ${_camwb_gui_widgets_dir}/editor/detail/DialectLexers.h
  ${_camwb_gui_widgets_dir}/editor/WordAddressLexer.cpp
  ${_camwb_gui_widgets_dir}/editor/HeidenhainLexer.cpp
  ${_camwb_gui_widgets_dir}/editor/ClLexers.cpp
  ${_camwb_gui_widgets_dir}/editor/NcFolding.cpp
  ${_camwb_gui_widgets_dir}/editor/detail/NcLexer.h
  ${_camwb_gui_widgets_dir}/editor/NcLexer.cpp
  ${_camwb_gui_widgets_dir}/editor/detail/NcFindBar.h
  ${_camwb_gui_widgets_dir}/editor/NcFindBar.cpp
  ${_camwb_gui_widgets_dir}/editor/RenumberDialog.h
  ${_camwb_gui_widgets_dir}/editor/RenumberDialog.cpp
  ${_camwb_gui_widgets_dir}/editor/CompareDialog.h
  ${_camwb_gui_widgets_dir}/editor/CompareDialog.cpp
  ${_camwb_gui_widgets_dir}/editor/ProgramInfoDialog.h
  ${_camwb_gui_widgets_dir}/editor/ProgramInfoDialog.cpp
  ${_camwb_gui_widgets_dir}/editor/NcEditor.h
  ${_camwb_gui_widgets_dir}/editor/NcEditor.cpp)
target_include_directories(camwb_gui_widgets PUBLIC ${_camwb_gui_widgets_dir}/.. ${PROJECT_BINARY_DIR}/generated)
# ChartsCore, RenderingContext2D/ContextOpenGL2: the simulator's chart (vtkChartXY in a context actor).
# RenderingFreeType: axis labels of the orientation marker (a private dependency of
# RenderingAnnotation; its target is imported with the components found in CamwbDependencies).
set(_camwb_gui_vtk_modules
  VTK::CommonCore VTK::CommonDataModel VTK::FiltersCore VTK::InteractionStyle VTK::RenderingCore
  VTK::RenderingOpenGL2 VTK::RenderingAnnotation VTK::RenderingFreeType VTK::RenderingUI
  VTK::ChartsCore VTK::RenderingContext2D VTK::RenderingContextOpenGL2)
target_link_libraries(camwb_gui_widgets
  PUBLIC Qt6::Widgets camwb_toolpath
  PRIVATE Qt6::OpenGL Qt6::OpenGLWidgets camwb_qscintilla ${_camwb_gui_vtk_modules})
# The NC editor speaks the NC module's dialects and diagnostics and runs its text tools.
target_link_libraries(camwb_gui_widgets PUBLIC camwb_nc camwb_sim)
# Registers VTK's object factories (OpenGL2 render classes, FreeType text) in this library.
vtk_module_autoinit(TARGETS camwb_gui_widgets MODULES ${_camwb_gui_vtk_modules})
target_compile_options(camwb_gui_widgets PRIVATE -Wall -Wextra -Wno-unused-parameter)
set_target_properties(camwb_gui_widgets PROPERTIES AUTOMOC ON POSITION_INDEPENDENT_CODE ON)
