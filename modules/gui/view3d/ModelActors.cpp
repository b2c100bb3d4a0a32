#include "gui/view3d/detail/ModelActors.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>

namespace camwb::gui {

namespace {

constexpr double kEdgeColor[3]{0.10, 0.10, 0.12};

}  // namespace

vtkSmartPointer<vtkActor> makeActor(vtkPolyData* data)
{
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

vtkSmartPointer<vtkActor> makeModelActor(const occ::DisplayMesh& mesh)
{
    const vtkIdType vertexCount = static_cast<vtkIdType>(mesh.positions.size() / 3);
    if (mesh.triangles.size() < 3 || vertexCount == 0)
        return nullptr;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->SetNumberOfPoints(vertexCount);
    for (vtkIdType i = 0; i < vertexCount; ++i)
        points->SetPoint(i, mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]);
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size() / 3),
                             static_cast<vtkIdType>(mesh.triangles.size()));
    // The model face of each triangle: picking and the task panels' face selection read it.
    vtkNew<vtkIntArray> faceOf;
    faceOf->SetName("face");
    const bool hasFaces = mesh.triangleFace.size() * 3 >= mesh.triangles.size();
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        const vtkIdType ids[3]{mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]};
        if (ids[0] < vertexCount && ids[1] < vertexCount && ids[2] < vertexCount) {
            triangles->InsertNextCell(3, ids);
            faceOf->InsertNextValue(hasFaces ? mesh.triangleFace[t / 3] : 0);
        }
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    data->SetPolys(triangles);
    data->GetCellData()->AddArray(faceOf);

    if (mesh.normals.size() == mesh.positions.size()) {
        vtkNew<vtkFloatArray> normals;
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(vertexCount);
        for (vtkIdType i = 0; i < vertexCount * 3; ++i)
            normals->SetValue(i, mesh.normals[static_cast<std::size_t>(i)]);
        data->GetPointData()->SetNormals(normals);
    } else {
        vtkNew<vtkPolyDataNormals> filter;
        filter->SetInputData(data);
        filter->SetFeatureAngle(30.0);
        filter->SplittingOn();
        filter->Update();
        data = filter->GetOutput();
    }

    auto actor = makeActor(data);
    auto* mapper = actor->GetMapper();
    mapper->ScalarVisibilityOff();
    // Push faces back so that the feature edges lying on them always win the depth test.
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 4.0);
    vtkProperty* property = actor->GetProperty();
    property->SetColor(kModelColor[0], kModelColor[1], kModelColor[2]);
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.25);
    property->SetSpecularPower(30.0);
    property->SetInterpolationToPhong();
    return actor;
}

vtkSmartPointer<vtkActor> makeEdgeActor(const occ::DisplayMesh& mesh)
{
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (const auto& edge : mesh.featureEdges) {
        if (edge.size() < 2)
            continue;
        lines->InsertNextCell(static_cast<vtkIdType>(edge.size()));
        for (const base::Vec3& p : edge)
            lines->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
    }
    if (lines->GetNumberOfCells() == 0)
        return nullptr;
    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    auto actor = makeActor(data);
    actor->GetMapper()->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(kEdgeColor[0], kEdgeColor[1], kEdgeColor[2]);
    actor->GetProperty()->SetLineWidth(1.5f);
    actor->GetProperty()->LightingOff();
    return actor;
}

}  // namespace camwb::gui
