// Model accessors that need no OCCT algorithms; loading, profiles and meshing live in their own files.
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <cmath>

namespace camwb::occ {

Model::Model() = default;

Model::Model(std::shared_ptr<const ModelData> data) : m_data(std::move(data)) {}

bool Model::empty() const { return !m_data || (m_data->shape.IsNull() && m_data->stlMesh.empty()); }

bool Model::hasBRep() const { return m_data && !m_data->shape.IsNull(); }

int Model::faceCount() const { return m_data ? static_cast<int>(m_data->faceInfos.size()) : 0; }

FaceInfo Model::face(int index) const
{
    if (index < 1 || index > faceCount())
        return {};
    return m_data->faceInfos[static_cast<std::size_t>(index - 1)];
}

int Model::topPlanarFace() const
{
    constexpr double kZTolerance = 1e-6;
    int best = 0;
    for (int i = 1; i <= faceCount(); ++i) {
        const FaceInfo& f = m_data->faceInfos[static_cast<std::size_t>(i - 1)];
        if (!f.planar || f.normal.z < 1 - kZAxisTolerance)
            continue;
        if (best == 0) {
            best = i;
            continue;
        }
        const FaceInfo& b = m_data->faceInfos[static_cast<std::size_t>(best - 1)];
        if (f.planeZ > b.planeZ + kZTolerance ||
            (std::abs(f.planeZ - b.planeZ) <= kZTolerance && f.areaMm2 > b.areaMm2))
            best = i;
    }
    return best;
}

base::Vec3 Model::boundsMin() const { return m_data ? m_data->boundsMin : base::Vec3{}; }

base::Vec3 Model::boundsMax() const { return m_data ? m_data->boundsMax : base::Vec3{}; }

}  // namespace camwb::occ
