// What a loaded model answers, as the OCCT kernel (libcamwb_occ_kernel.so, loaded on first use by
// Kernel.cpp) implements it. OCCT-free: Model forwards to it through these virtual functions, so
// the programs link no OCCT library and a command that reads no model never loads one.
// The kernel and its callers are built together; the table carries an ABI number all the same,
// so a stale kernel beside a newer program is refused with a message instead of crashing.
#pragma once

#include "occ/Model.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::occ {

// A unit normal counts as +-Z when 1 - |n.z| is below this (about 4.5e-5 rad).
inline constexpr double kZAxisTolerance = 1e-9;

class ModelImpl {
public:
    virtual ~ModelImpl() = default;

    std::string path;
    std::vector<FaceInfo> faceInfos;  // [i - 1] describes face i
    std::vector<EdgeInfo> edgeInfos;  // [i - 1] describes edge i
    base::Vec3 boundsMin;
    base::Vec3 boundsMax;

    int faceCount() const { return static_cast<int>(faceInfos.size()); }
    int edgeCount() const { return static_cast<int>(edgeInfos.size()); }
    FaceInfo face(int index) const
    {
        return index < 1 || index > faceCount() ? FaceInfo{} : faceInfos[static_cast<std::size_t>(index - 1)];
    }
    EdgeInfo edge(int index) const
    {
        return index < 1 || index > edgeCount() ? EdgeInfo{} : edgeInfos[static_cast<std::size_t>(index - 1)];
    }

    // As Model's functions of the same names (Model.h says what each does).
    virtual bool empty() const = 0;
    virtual bool hasBRep() const = 0;
    virtual base::Result<geom::Profile> planarFaceOuterProfile(int faceIndex, double toleranceMm) const = 0;
    virtual base::Result<geom::Region> planarFaceRegion(int faceIndex, double toleranceMm) const = 0;
    virtual base::Result<std::vector<geom::Profile>> edgeChains(const std::vector<int>& edgeIndices,
                                                                double toleranceMm) const = 0;
    virtual std::vector<geom::Hole> holes() const = 0;
    virtual base::Result<geom::Hole> circleEdgeAsHole(int edgeIndex) const = 0;
    virtual DisplayMesh mesh(double linearDeflectionMm) const = 0;
    virtual base::Result<std::vector<std::vector<base::Vec2>>> sectionLoops(double z, double toleranceMm) const = 0;
    virtual base::Result<std::shared_ptr<const ModelImpl>> inFrame(const base::Vec3& origin, const base::Vec3& xAxis,
                                                                   const base::Vec3& zAxis) const = 0;
    virtual std::optional<base::Vec3> cylinderAxis(int faceIndex) const = 0;
    virtual base::Result<SwarfFace> swarfFace(int faceIndex, int edgeIndex) const = 0;
    virtual std::optional<Gouge> firstGouge(const std::vector<ToolPose>& poses, double radiusMm, double fluteLengthMm,
                                            double toleranceMm) const = 0;
};

// The kernel's entry points: the one C symbol it exports (kKernelEntryPoint) returns this table.
struct KernelTable {
    int abi = 0;  // kKernelAbi when kernel and program were built together
    base::Result<std::shared_ptr<const ModelImpl>> (*load)(const std::string& path,
                                                           const ProgressFn& progress) = nullptr;
    base::Status (*writeExamplePart)(const std::string& stepPath) = nullptr;
    base::Status (*writeFiveAxisExamplePart)(const std::string& stepPath) = nullptr;
    base::Status (*writeFiveAxisExampleBlank)(const std::string& stepPath) = nullptr;
    base::Status (*writeMouldExamplePart)(const std::string& stepPath) = nullptr;
};

// Raise whenever ModelImpl or KernelTable changes.
inline constexpr int kKernelAbi = 1;
inline constexpr const char* kKernelEntryPoint = "camwb_occ_kernel_table";

// The kernel, loaded on the first call (thread-safe); later calls return the same table, or the
// same error: "the OCCT kernel is not at <places>" or "the OCCT kernel <path> could not be loaded:
// <why>" (CAMWB_OCC_KERNEL, when set, names the library to load instead of the installed or built one).
base::Result<const KernelTable*> kernel();

}  // namespace camwb::occ
