# Finds the Debian 12 packages CAM Workbench builds against (scripts/install-deps.sh installs them).
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Qml Concurrent Test LinguistTools)
find_package(OpenCASCADE REQUIRED)  # Debian 12: 7.6.3 (its config accepts only exact versions)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)  # Debian 12: 3.4.0, header-only
find_package(GTest REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)
pkg_check_modules(MINIZIP REQUIRED IMPORTED_TARGET minizip)  # Fusion 360's .tools archives

if(NOT CAMWB_BUILD_GUI)
  return()  # VTK and QScintilla are the GUI's alone
endif()
# Debian's VTK config refers to MPI::MPI_C, so C must be enabled and MPI found before VTK.
find_package(MPI COMPONENTS C)
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonColor FiltersCore FiltersSources InteractionStyle
  RenderingCore RenderingOpenGL2 RenderingAnnotation ChartsCore RenderingContext2D RenderingContextOpenGL2)

# QScintilla for Qt6 ships no CMake config on Debian.
find_library(QSCINTILLA_LIBRARY NAMES qscintilla2_qt6 REQUIRED)
find_path(QSCINTILLA_INCLUDE_DIR NAMES Qsci/qsciscintilla.h
  PATHS /usr/include/x86_64-linux-gnu/qt6 /usr/include/qt6 REQUIRED)
add_library(camwb_qscintilla INTERFACE)
target_link_libraries(camwb_qscintilla INTERFACE ${QSCINTILLA_LIBRARY} Qt6::Widgets)
target_include_directories(camwb_qscintilla SYSTEM INTERFACE ${QSCINTILLA_INCLUDE_DIR})

find_program(XVFB_RUN xvfb-run)
