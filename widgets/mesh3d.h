#pragma once
/// CPU tessellation of a pkm::Scene3D for the 3D view, no GL: boxes, cylinders with caps and
/// UV spheres become indexed triangles with outward unit normals (flat on box faces and caps,
/// smooth on round surfaces) and a per-vertex colour from the part's role; the ground grid
/// becomes lines. Counter-clockwise triangles seen from outside, so back faces can be culled.
///
/// Colours follow the 2D view's palette (SceneStyle): greys for the ground and the guides, the
/// link green, the rod purple, the platform teal, a dark motor and a light metallic screw, so a
/// projected picture reads the same in 2D and 3D on the light background.

#include "scene3d.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QColor>

#include <array>
#include <cstdint>
#include <vector>

namespace pkm {

/// How a part looks: its base colour (sRGB) and the strength of its highlight.
struct PartFinish {
    QColor colour;
    float specular = 0.2f; ///< 0 matte … 1 polished metal
};
PartFinish partFinish(PartRole role);

/// Laid out for a vertex buffer: 10 floats.
struct MeshVertex {
    std::array<float, 3> position; ///< mm
    std::array<float, 3> normal; ///< unit, outward
    std::array<float, 4> colour; ///< sRGB red, green, blue in [0, 1]; alpha: specular strength
};
static_assert(sizeof(MeshVertex) == 10 * sizeof(float), "MeshVertex must be tightly packed");

struct LineVertex {
    std::array<float, 3> position; ///< mm
    std::array<float, 4> colour; ///< sRGB with alpha
};
static_assert(sizeof(LineVertex) == 7 * sizeof(float), "LineVertex must be tightly packed");

class Mesh3D
{
public:
    static constexpr int cylinderSegments = 32;
    static constexpr int sphereSlices = 24; ///< around the pole axis (z)
    static constexpr int sphereStacks = 12; ///< from pole to pole

    const std::vector<MeshVertex> &vertices() const { return m_vertices; }
    /// Triangles, three indices each, counter-clockwise seen from outside.
    const std::vector<std::uint32_t> &indices() const { return m_indices; }
    std::size_t triangleCount() const { return m_indices.size() / 3; }
    bool isEmpty() const { return m_indices.empty(); }
    void clear();

    /// Appends a solid's surface in the finish's colour. A box or a cylinder of zero length,
    /// and a solid of zero size, add nothing.
    void appendSolid(const Solid &solid, const PartFinish &finish);
    void appendSolid(const Solid &solid) { appendSolid(solid, partFinish(solid.role)); }

    /// Box around all vertices (empty for an empty mesh).
    Eigen::AlignedBox3d bounds() const;

    /// One mesh for a whole model, each solid in its role's colour.
    static Mesh3D fromScene(const Scene3D &scene);

private:
    void appendBox(const Solid &solid, const std::array<float, 4> &colour);
    void appendCylinder(const Solid &solid, const std::array<float, 4> &colour);
    void appendSphere(const Solid &solid, const std::array<float, 4> &colour);
    std::uint32_t addVertex(
        const Eigen::Vector3d &position, const Eigen::Vector3d &normal, const std::array<float, 4> &colour);
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);

    std::vector<MeshVertex> m_vertices;
    std::vector<std::uint32_t> m_indices;
};

/// The ground grid: line pairs in the plane just below the extent.
struct GroundGrid {
    std::vector<LineVertex> vertices; ///< GL_LINES: two per line
    double spacing = 0.0; ///< between neighbouring lines, mm (1, 2 or 5 × 10ⁿ)
    double y = 0.0; ///< height of the plane, mm
    Eigen::AlignedBox3d bounds; ///< the rectangle covered (flat in y)
};

/// A grid a little below `extent` (its y = extent.min.y, lowered by a thousandth of the
/// extent's size so no face lies in it), covering the extent's x–z rectangle with a margin of
/// a quarter of its size, snapped to whole lines. The spacing is the round number that gives
/// about 16 lines across; lines on a multiple of the next power of ten are stronger. An empty
/// extent gets a grid of ±100 mm about the origin.
GroundGrid groundGrid(const Eigen::AlignedBox3d &extent);

/// What fitting the view frames: the extent and every solid.
Eigen::AlignedBox3d modelBounds(const Scene3D &scene);

} // namespace pkm
