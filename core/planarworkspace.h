#pragma once
/// Workspaces and singularity maps of mechanisms whose two outputs are a point of the plane
/// (MOMA's platform, the O-X glide's platform). A map is a pure function of (design, grid)
/// that fills a caller's buffer row by row: no allocation per cell, rows in parallel,
/// cancellable between rows.
///
/// Units: mm for positions and areas (mm²); map values are dimensionless (det J of a
/// length-to-length Jacobian, its condition number).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <atomic>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pkm {

namespace capability {
struct CellLimits;
}

enum class MapQuantity {
    Determinant, ///< det J = det J_x / det J_q; 0 at a direct, ±∞ at an inverse singularity
    Condition,   ///< condition number of J (σ_max/σ_min, ≥ 1); +∞ at any singularity
    /// The orientation range of a platform that turns: the total width of the platform angles
    /// φ at which it can be held at (x, y) in the design's working modes, rad (0 … 2π); NaN
    /// where no φ holds it. Only where PlanarWorkspace::offers() says so.
    OrientationRange,
    /// What the actuators deliver (capability.h), mapped by capabilitymap.h, not by
    /// fillMapRow(): each cell is solved and evaluated, in core units; NaN where unreachable.
    ForceWorst,      ///< largest platform force in its weakest direction; 0 at a direct singularity
    SpeedWorst,      ///< largest platform speed in its slowest direction; 0 at an inverse one
    ResolutionWorst, ///< largest error from half a step per actuator; ∞ at a direct one
    StiffnessWorst,  ///< smallest eigenvalue of K = Jᵀ·K_q·J; 0 at a direct one
    /// Where the design meets every stated requirement on the capability (1) or not (0).
    Specification,
    /// The first-order worst-case error of the platform point from the design's tolerances
    /// (tolerance.h), mm, mapped by tolerancemap.h; +∞ at a direct singularity.
    ToleranceWorst,
};

/// Whether `quantity` is one of what the actuators deliver (capabilitymap.h computes it).
constexpr bool isCapability(MapQuantity quantity)
{
    return quantity >= MapQuantity::ForceWorst && quantity <= MapQuantity::Specification;
}

/// Whether every cell of a map of `quantity` is a value of the pose solved there, with a name
/// and a unit of its own (what the actuators deliver, the worst-case error): such a map has a
/// sequential colour scale from 0 and a title in words.
constexpr bool isPoseValue(MapQuantity quantity)
{
    return isCapability(quantity) || quantity == MapQuantity::ToleranceWorst;
}

/// A regular grid of cell centres over a box: cell (column c, row r) has its centre at
/// (xMin + (c + ½)·dx, yMin + (r + ½)·dy); row 0 is the bottom row.
struct MapGrid {
    Eigen::AlignedBox2d bounds;
    int columns = 0;
    int rows = 0;

    double dx() const { return bounds.sizes().x() / columns; }
    double dy() const { return bounds.sizes().y() / rows; }
    double cellArea() const { return dx() * dy(); }
    double x(int column) const { return bounds.min().x() + (column + 0.5) * dx(); }
    double y(int row) const { return bounds.min().y() + (row + 0.5) * dy(); }
    std::size_t cells() const { return static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows); }
};

/// Leaves a new element uninitialised where std::allocator would zero it: every cell of a map
/// is written by its computation, and zeroing a 3000² map and its margins first (72 MB) costs
/// a quarter of computing them, on one thread where the map runs on all.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
    using std::allocator<T>::allocator;
    UninitialisedAllocator() = default;
    template <class U>
    UninitialisedAllocator(const UninitialisedAllocator<U> &) noexcept
    {
    }
    template <class U>
    void construct(U *at) noexcept
    {
        ::new (static_cast<void *>(at)) U;
    }
    template <class U, class... Arguments>
    void construct(U *at, Arguments &&...arguments)
    {
        ::new (static_cast<void *>(at)) U(std::forward<Arguments>(arguments)...);
    }
};
/// The cells of a map, row by row: resized without being zeroed (UninitialisedAllocator).
using MapCells = std::vector<float, UninitialisedAllocator<float>>;

/// A singular curve in the plane of the outputs, as a polyline (mm).
struct SingularCurve {
    enum class Type { Inverse, Direct } type = Type::Inverse;
    std::string label; ///< "leg 1 ⟂ guide", "links collinear"
    std::vector<Eigen::Vector2d> points;
};

/// An area of the workspace known in closed form, which reports give beside the grid's estimate.
struct ExactArea {
    std::string key;    ///< "area" for the design's own modes, else a name of its own ("area_O")
    std::string symbol; ///< as printed ("A", "A_O")
    std::string label;  ///< English source, QT_TRANSLATE_NOOP("Sheet", …): the sheet translates it
    double area = 0.0;  ///< mm²
};

/// Implemented by mechanisms with a planar workspace (Mechanism::planarWorkspace()).
class PlanarWorkspace
{
public:
    virtual ~PlanarWorkspace() = default;

    /// A box that holds the whole workspace of the design's current modes (mm).
    virtual Eigen::AlignedBox2d workspaceBounds() const = 0;
    /// Fills `values` (and `margins`, if not empty) for the `values.size()` cells of one row at
    /// height y, starting at x0 with spacing dx. A cell the design cannot reach in its current
    /// working and assembly modes gets NaN in both. `margins` receives the dimensionless
    /// singularity margin (0 at a singularity, up to 1). Thread-safe, never allocates.
    virtual void fillMapRow(MapQuantity quantity, double y, double x0, double dx, std::span<float> values,
                            std::span<float> margins) const = 0;
    /// The singular curves inside the workspace, for drawing over a map.
    virtual std::vector<SingularCurve> singularCurves() const = 0;
    /// What a singular curve of `type` means for this mechanism, for a legend: "link ⟂ guide".
    virtual std::string singularityMeaning(SingularCurve::Type type) const = 0;
    /// The areas known exactly, the design's own modes first (key "area"); none by default,
    /// where only the grid estimates the area.
    virtual std::vector<ExactArea> exactAreas() const { return {}; }
    /// Whether fillMapRow() maps `quantity`: det J and κ everywhere, the orientation range only
    /// for a platform that turns (a 3-DOF planar parallel design); never the capability's.
    virtual bool offers(MapQuantity quantity) const
    {
        return quantity == MapQuantity::Determinant || quantity == MapQuantity::Condition;
    }
    /// Whether fillCapabilityRow() maps what the actuators deliver. Where it does not, a
    /// capability map solves and evaluates every cell (capabilitymap.cpp).
    virtual bool fillsCapabilityRows() const { return false; }
    /// Fills one row of a map of `limits.quantity` (capabilitycell.h; core units, ∞ where it
    /// is undefined) and `margins` (the same size), as fillMapRow() fills det J: NaN in both
    /// where the design cannot reach in its current modes (a platform that turns: at φ =
    /// phi_map). Thread-safe, never allocates.
    virtual void fillCapabilityRow(const capability::CellLimits &limits, double y, double x0, double dx,
                                   std::span<float> values, std::span<float> margins) const
    {
        (void)limits, (void)y, (void)x0, (void)dx, (void)values, (void)margins;
    }
};

/// Below this margin a cell counts as near-singular (≈ 3° from the singular pose).
inline constexpr double nearSingularMargin = 0.05;

struct MapSummary {
    MapGrid grid;
    std::size_t reachableCells = 0;
    std::size_t nearSingularCells = 0;
    double min = 0.0; ///< over the reachable, finite cells (0 when there are none)
    double max = 0.0;
    double area = 0.0; ///< reachable cells × cell area, mm²
    /// The box of the reachable cells (their edges, mm; empty when none), filled by a planar
    /// workspace's computeMap() and summariseMap() only.
    Eigen::AlignedBox2d reachableBox;
    double seconds = 0.0;
    bool cancelled = false;
};

/// Computes a map over `grid` into `values` (grid.cells() floats, row-major from the bottom
/// row; NaN where unreachable) on `threads` threads (0: all cores). `margins` may be empty.
/// Stops between rows once `*cancel` becomes true and returns with summary.cancelled set.
MapSummary computeMap(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid,
                      std::span<float> values, std::span<float> margins = {},
                      const std::atomic<bool> *cancel = nullptr, int threads = 0);

/// computeMap()'s summary without keeping the cells: each thread fills and tallies one row at
/// a time in a buffer of its own, so memory does not grow with the grid. near-singular cells
/// are counted only `withMargins`.
MapSummary summariseMap(const PlanarWorkspace &workspace, MapQuantity quantity, const MapGrid &grid,
                        bool withMargins = true, const std::atomic<bool> *cancel = nullptr, int threads = 0);

/// Whether a map cell is reachable: finite or infinite values are, NaN is not.
inline bool reachableCell(float value)
{
    return !std::isnan(value);
}

/// The first and the last reachable cell of a map row (columns), or nothing when none is:
/// only these two can widen a box of the reachable cells, so a row is read from either end
/// and the cells between are never touched.
std::optional<std::pair<int, int>> reachableEnds(std::span<const float> row);

/// The grid of `resolution` cells along the longer side of the workspace bounds, with square
/// cells (resolution ≥ 2).
MapGrid squareGrid(const Eigen::AlignedBox2d &bounds, int resolution);

/// The outline of the reachable cells (finite values) as segments between cell edges: each
/// pair of points is one segment of the boundary, in mm.
std::vector<Eigen::Vector2d> workspaceOutline(const MapGrid &grid, std::span<const float> values);

} // namespace pkm
