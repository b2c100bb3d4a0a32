// Model's functions: each asks the OCCT kernel's ModelImpl, loading the kernel on Model::load.
// An empty Model (nothing loaded) answers with nothing: no faces, no edges, an error to a question.
#include "occ/Model.h"

#include "occ/detail/ModelImpl.h"

#include <cmath>

namespace camwb::occ {
namespace {

base::Error nothingLoaded() { return base::makeError("no model is loaded"); }

}  // namespace

Model::Model() = default;

Model::Model(std::shared_ptr<const ModelImpl> impl) : m_impl(std::move(impl)) {}

base::Result<Model> Model::load(const std::string& path, const ProgressFn& progress)
{
    const base::Result<const KernelTable*> loaded = kernel();
    if (!loaded)
        return base::makeError(loaded.error().message, path);
    base::Result<std::shared_ptr<const ModelImpl>> impl = loaded.value()->load(path, progress);
    if (!impl)
        return impl.error();
    return Model(std::move(impl).value());
}

bool Model::empty() const { return !m_impl || m_impl->empty(); }

bool Model::hasBRep() const { return m_impl && m_impl->hasBRep(); }

int Model::faceCount() const { return m_impl ? m_impl->faceCount() : 0; }

FaceInfo Model::face(int index) const { return m_impl ? m_impl->face(index) : FaceInfo{}; }

int Model::topPlanarFace() const
{
    constexpr double kZTolerance = 1e-6;
    int best = 0;
    for (int i = 1; i <= faceCount(); ++i) {
        const FaceInfo f = face(i);
        if (!f.planar || f.normal.z < 1 - kZAxisTolerance)
            continue;
        if (best == 0) {
            best = i;
            continue;
        }
        const FaceInfo b = face(best);
        if (f.planeZ > b.planeZ + kZTolerance ||
            (std::abs(f.planeZ - b.planeZ) <= kZTolerance && f.areaMm2 > b.areaMm2))
            best = i;
    }
    return best;
}

base::Result<geom::Profile> Model::planarFaceOuterProfile(int faceIndex, double toleranceMm) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->planarFaceOuterProfile(faceIndex, toleranceMm);
}

base::Result<geom::Region> Model::planarFaceRegion(int faceIndex, double toleranceMm) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->planarFaceRegion(faceIndex, toleranceMm);
}

int Model::edgeCount() const { return m_impl ? m_impl->edgeCount() : 0; }

EdgeInfo Model::edge(int index) const { return m_impl ? m_impl->edge(index) : EdgeInfo{}; }

base::Result<std::vector<geom::Profile>> Model::edgeChains(const std::vector<int>& edgeIndices,
                                                           double toleranceMm) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->edgeChains(edgeIndices, toleranceMm);
}

std::vector<geom::Hole> Model::holes() const { return m_impl ? m_impl->holes() : std::vector<geom::Hole>{}; }

base::Result<geom::Hole> Model::circleEdgeAsHole(int edgeIndex) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->circleEdgeAsHole(edgeIndex);
}

DisplayMesh Model::mesh(double linearDeflectionMm) const
{
    return m_impl ? m_impl->mesh(linearDeflectionMm) : DisplayMesh{};
}

base::Result<std::vector<std::vector<base::Vec2>>> Model::sectionLoops(double z, double toleranceMm) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->sectionLoops(z, toleranceMm);
}

base::Vec3 Model::boundsMin() const { return m_impl ? m_impl->boundsMin : base::Vec3{}; }

base::Vec3 Model::boundsMax() const { return m_impl ? m_impl->boundsMax : base::Vec3{}; }

base::Result<Model> Model::inFrame(const base::Vec3& origin, const base::Vec3& xAxis, const base::Vec3& zAxis) const
{
    if (!m_impl)
        return nothingLoaded();
    base::Result<std::shared_ptr<const ModelImpl>> impl = m_impl->inFrame(origin, xAxis, zAxis);
    if (!impl)
        return impl.error();
    return Model(std::move(impl).value());
}

std::optional<base::Vec3> Model::cylinderAxis(int faceIndex) const
{
    return m_impl ? m_impl->cylinderAxis(faceIndex) : std::nullopt;
}

base::Result<SwarfFace> Model::swarfFace(int faceIndex, int edgeIndex) const
{
    if (!m_impl)
        return nothingLoaded();
    return m_impl->swarfFace(faceIndex, edgeIndex);
}

std::optional<Gouge> Model::firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                       double toleranceMm) const
{
    return m_impl ? m_impl->firstGouge(poses, radiusMm, fluteLengthMm, toleranceMm) : std::nullopt;
}

}  // namespace camwb::occ
