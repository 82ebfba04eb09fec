// pkmstudio._core.Map and .Workspace: `pkm map` and `pkm workspace` computed in-process
// (cli/cliworkspace.h), their buffers handed to NumPy without a copy: a map's `values` array
// has the Map as its base and lives as long as either does.

#include "bindings.h"

#include "cli/clicapabilitymap.h"
#include "cli/cliworkspace.h"
#include "report/workspaceanalysis.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

namespace pkm::python {

namespace {

struct MapPy {
    std::shared_ptr<const cli::CommandMap> computed;
    MechanismPtr mechanism;
    int resolution = cli::defaultGrid;
};

struct WorkspacePy {
    std::shared_ptr<const cli::CommandWorkspace> computed;
    std::string json; ///< what `pkm workspace --json` prints
};

/// The options of `pkm map` or `pkm workspace`, checked by the command line's own parser, so
/// that a bad grid, quantity or requirement gets the command line's sentence.
cli::Invocation invocationOf(const std::string &command, const std::optional<std::string> &quantity, int grid,
    const std::vector<std::string> &requirements)
{
    std::vector<std::string> arguments {command, "DESIGN", "--grid", std::to_string(grid)};
    if (quantity) {
        arguments.emplace_back("--quantity");
        arguments.push_back(*quantity);
    }
    for (const std::string &requirement : requirements) {
        arguments.emplace_back("--require");
        arguments.push_back(requirement);
    }
    return take(cli::parseArguments(arguments));
}

/// A float buffer of the grid as a 2-D array (rows from the bottom up, columns from the left)
/// that shares the memory; `owner` keeps it alive.
py::array gridArray(const MapGrid &grid, const MapCells &values, const py::object &owner)
{
    const auto columns = static_cast<py::ssize_t>(grid.columns);
    const auto rows = static_cast<py::ssize_t>(grid.rows);
    const auto item = static_cast<py::ssize_t>(sizeof(float));
    // read-only: the map is a result, and a Map shared by several arrays stays the same
    py::array_t<float> array({rows, columns}, {columns * item, item}, values.data(), owner);
    array.attr("setflags")(py::arg("write") = false);
    return array;
}

py::dict boundsDict(const Eigen::AlignedBox2d &box)
{
    py::dict bounds;
    bounds["x_min"] = box.min().x();
    bounds["x_max"] = box.max().x();
    bounds["y_min"] = box.min().y();
    bounds["y_max"] = box.max().y();
    return bounds;
}

py::tuple extentOf(const MapGrid &grid)
{
    return py::make_tuple(grid.bounds.min().x(), grid.bounds.max().x(), grid.bounds.min().y(), grid.bounds.max().y());
}

/// The x (or y) of the cell centres.
py::array_t<double> centres(const MapGrid &grid, bool x)
{
    const int count = x ? grid.columns : grid.rows;
    py::array_t<double> array(count);
    auto out = array.mutable_unchecked<1>();
    for (int i = 0; i < count; ++i)
        out(i) = x ? grid.x(i) : grid.y(i);
    return array;
}

py::list singularCurves(const Mechanism &mechanism)
{
    py::list list;
    const PlanarWorkspace *workspace = mechanism.planarWorkspace();
    if (!workspace)
        return list;
    for (const SingularCurve &curve : workspace->singularCurves()) {
        py::array_t<double> points({static_cast<py::ssize_t>(curve.points.size()), py::ssize_t(2)});
        auto out = points.mutable_unchecked<2>();
        for (std::size_t i = 0; i < curve.points.size(); ++i) {
            out(py::ssize_t(i), 0) = curve.points[i].x();
            out(py::ssize_t(i), 1) = curve.points[i].y();
        }
        py::dict entry;
        entry["type"] = curve.type == SingularCurve::Type::Inverse ? "inverse" : "direct";
        entry["label"] = curve.label;
        entry["points"] = points;
        list.append(entry);
    }
    return list;
}

const MapGrid &gridOf(const MapPy &map)
{
    return map.computed->map.grid;
}

} // namespace

void bindMaps(py::module_ &module)
{
    py::class_<MapPy>(module, "Map",
        "A map of one quantity over the workspace, as `pkm map` computes it. values[r, c] is the cell "
        "in row r (from the bottom) and column c (from the left), NaN where the design cannot reach; "
        "plot it with imshow(map.values, origin='lower', extent=map.extent).")
        .def_property_readonly("values", [](const py::object &self) {
            const MapPy &map = self.cast<const MapPy &>();
            return gridArray(gridOf(map), map.computed->map.values, self);
        }, "The map (float32, rows × columns), sharing the map's memory (read-only).")
        .def_property_readonly("margins", [](const py::object &self) {
            const MapPy &map = self.cast<const MapPy &>();
            return gridArray(gridOf(map), map.computed->map.margins, self);
        }, "The singularity margin of each cell: 0 at a singularity, up to 1.")
        .def_property_readonly("quantity", [](const MapPy &map) { return std::string(cli::quantityKey(map.computed->quantity)); })
        .def_property_readonly("title", [](const MapPy &map) { return cli::quantityTitle(*map.mechanism, map.computed->quantity); })
        .def_property_readonly("unit", [](const MapPy &map) { return cli::capabilityUnit(*map.mechanism, map.computed->quantity); })
        .def_property_readonly("resolution", [](const MapPy &map) { return map.resolution; },
            "The grid as asked: cells along the longer side.")
        .def_property_readonly("shape", [](const MapPy &map) { return py::make_tuple(gridOf(map).rows, gridOf(map).columns); })
        .def_property_readonly("extent", [](const MapPy &map) { return extentOf(gridOf(map)); },
            "(x_min, x_max, y_min, y_max) of the grid, mm: matplotlib's extent.")
        .def_property_readonly("cell_size", [](const MapPy &map) { return gridOf(map).dx(); })
        .def_property_readonly("x", [](const MapPy &map) { return centres(gridOf(map), true); }, "The columns' centres, mm.")
        .def_property_readonly("y", [](const MapPy &map) { return centres(gridOf(map), false); }, "The rows' centres, mm.")
        .def_property_readonly("area", [](const MapPy &map) { return map.computed->map.summary.area; },
            "The reachable cells' area, mm².")
        .def_property_readonly("min", [](const MapPy &map) { return map.computed->map.summary.min; },
            "The least value over the finite cells.")
        .def_property_readonly("max", [](const MapPy &map) { return map.computed->map.summary.max; })
        .def_property_readonly("reachable_cells", [](const MapPy &map) { return map.computed->map.summary.reachableCells; })
        .def_property_readonly("near_singular_cells",
            [](const MapPy &map) { return map.computed->map.summary.nearSingularCells; })
        .def_property_readonly("seconds", [](const MapPy &map) { return map.computed->map.summary.seconds; },
            "How long the map took to compute.")
        .def_property_readonly("singular_curves", [](const MapPy &map) { return singularCurves(*map.mechanism); },
            "The singular curves inside the workspace: [{'type', 'label', 'points' (n × 2, mm)}, …].")
        .def("__repr__", [](const MapPy &map) {
            const MapGrid &grid = gridOf(map);
            return "<pkmstudio.Map " + std::string(cli::quantityKey(map.computed->quantity)) + " "
                + std::to_string(grid.columns) + "×" + std::to_string(grid.rows) + ">";
        });

    py::class_<WorkspacePy>(module, "Workspace",
        "The reachable workspace of the design's modes, as `pkm workspace` computes it.")
        .def_property_readonly("reachable", [](const WorkspacePy &workspace) {
            const cli::ComputedMap &map = workspace.computed->map;
            py::array_t<bool> reachable({py::ssize_t(map.grid.rows), py::ssize_t(map.grid.columns)});
            bool *out = reachable.mutable_data();
            for (std::size_t i = 0; i < map.values.size(); ++i)
                out[i] = report::reachableCell(map.values[i]);
            return reachable;
        }, "Whether each cell (rows from the bottom) is reachable, a new bool array.")
        .def_property_readonly("det", [](const py::object &self) {
            const WorkspacePy &workspace = self.cast<const WorkspacePy &>();
            return gridArray(workspace.computed->map.grid, workspace.computed->map.values, self);
        }, "det J over the grid, NaN where unreachable (shares the workspace's memory).")
        .def_property_readonly("extent", [](const WorkspacePy &workspace) { return extentOf(workspace.computed->map.grid); })
        .def_property_readonly("grid_bounds", [](const WorkspacePy &workspace) { return boundsDict(workspace.computed->map.grid.bounds); })
        .def_property_readonly("_json", [](const WorkspacePy &workspace) { return workspace.json; });

    module.def("_map", [](const DesignPy &design, const std::optional<std::string> &quantity, int grid,
                            const std::vector<std::string> &require) {
        const cli::Invocation invocation = invocationOf("map", quantity, grid, require);
        std::shared_ptr<const cli::CommandMap> computed;
        {
            py::gil_scoped_release unlocked;
            auto result = cli::computeCommandMap(design.prepared, invocation);
            py::gil_scoped_acquire locked;
            computed = std::make_shared<const cli::CommandMap>(take(std::move(result)));
        }
        return MapPy {computed, design.prepared.mechanism, grid};
    });
    module.def("_workspace", [](const DesignPy &design, int grid, const std::vector<std::string> &require) {
        const cli::Invocation invocation = invocationOf("workspace", std::nullopt, grid, require);
        WorkspacePy workspace;
        {
            py::gil_scoped_release unlocked;
            auto result = cli::computeCommandWorkspace(design.prepared, invocation);
            py::gil_scoped_acquire locked;
            workspace.computed = std::make_shared<const cli::CommandWorkspace>(take(std::move(result)));
        }
        workspace.json = cli::workspaceJson(design.prepared, *workspace.computed, grid);
        return workspace;
    });
}

} // namespace pkm::python
