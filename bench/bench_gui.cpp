// Benchmark: after a slider move, how long until the linkage view, the plots and the panels
// have repainted? The main window is shown at 1920×1080 on the offscreen platform and θ is
// swept over its range as a slider drag would; each step is one document change followed by
// the repaint of every widget it changed (view, plots, panels, values, status bar), done
// before the step's time is taken. Target: ≤ 8 ms per step (issue: foundation).
//
// With a MOMA preset as the second argument ("bench_gui 8 moma-3a") the platform is dragged
// instead, along a loop inside the workspace, while the det J map is visible (issue: MOMA):
// each step is a drag of the platform handle, then the repaint of the view, the map's pose
// marker, the ghosts, panels and values.
//
// With "pp-3rpr" (issue: leg library) the 3-RPR's platform is dragged the same way while its
// map is visible: each step solves all three struts' inverse kinematics and repaints. Target:
// ≤ 8 ms, as for MOMA.
//
// With "3d" as the third argument ("bench_gui 33 pjoint-prototype 3d", under Xvfb with Mesa's
// software renderer) the 3D tab is shown instead of the 2D view: each step includes building
// the solid model, tessellating, uploading and drawing it, and waiting for the GL frame to
// finish (issue: 3D view).
//
// With "shapes" as the third argument ("bench_gui 8 moma-3a shapes") the same drag runs with
// View ▸ Velocity and Force Shapes off and on, in alternating rounds, and the figure is what
// the shapes add to a step's median (issue: actuator capability; target ≤ 1 ms), beside the
// step's own target.
//
// With "edit" as the third argument ("bench_gui 50 moma-3a edit") a design parameter (the
// first link, l1, ±1 % in turn) is edited as the Design panel does, and each step lasts from
// the edit until the new map is on screen: the new mechanism, the debounce that lets a burst
// of edits compute once (30 ms), the map on a worker thread, and the repaint (issue: maps at
// the hardware limit; target ≤ 50 ms at the default grid).
#include "benchmachine.h"
#include "document/document.h"
#include "gui/mainwindow.h"
#include "kinds/workspacepanel.h"
#include "linkageview.h"
#include "linkageview3d.h"
#include "units.h"
#include "workspacemapview.h"

#include <QApplication>
#include <QTabWidget>
#include <QElapsedTimer>
#include <QStandardPaths>

#include <algorithm>
#include <cstdio>
#include <vector>

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? QByteArray("offscreen")
                                                                     : qgetenv("QT_QPA_PLATFORM"));
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    std::printf("machine: %s\n", pkm::bench::cpuText().c_str());
    const double limitMs = argc > 1 ? std::atof(argv[1]) : 8.0;
    const QString preset = argc > 2 ? QString::fromLocal8Bit(argv[2]) : QString();
    const bool in3d = argc > 3 && QByteArray(argv[3]) == "3d";
    const bool shapes = argc > 3 && QByteArray(argv[3]) == "shapes";
    const bool edit = argc > 3 && QByteArray(argv[3]) == "edit";

    pkm::MainWindow window;
    window.setGeometry(0, 0, 1920, 1080);
    window.show();
    QApplication::processEvents();
    if (!preset.isEmpty() && !window.openDesign(preset)) {
        std::printf("error: cannot open %s\n", qPrintable(preset));
        return 1;
    }
    const bool platform = window.document()->mechanism()->planarWorkspace() != nullptr;
    // the map on screen: the generic panel's, or the one inside a kind's own panel
    pkm::WorkspaceMapView *map = window.workspacePanel()->mapView();
    if (platform) {
        // wait for the map, so that it is on screen during the drag
        QElapsedTimer wait;
        wait.start();
        for (pkm::WorkspaceMapView *candidate : window.findChildren<pkm::WorkspaceMapView *>())
            if (candidate->isVisible())
                map = candidate;
        while ((map->busy() || map->summary().reachableCells == 0) && wait.elapsed() < 10000)
            QApplication::processEvents(QEventLoop::AllEvents, 10);
        if (map->summary().reachableCells == 0 || !map->isVisible()) {
            std::printf("error: the map is not visible\n");
            return 1;
        }
    }
    if (edit) {
        if (!platform)
            return std::printf("error: %s has no map\n", qPrintable(preset)), 1;
        const double l1 = window.document()->mechanism()->parameters().at("l1"); // mm
        std::vector<double> times, calls;
        QElapsedTimer timer;
        for (int i = 0; i < 40; ++i) {
            const int generation = map->generation();
            const double area = map->area();
            timer.start();
            // display units: mm
            if (!window.document()->setParameter(QStringLiteral("l1"), l1 * (i % 2 == 0 ? 1.01 : 1.0))) {
                std::printf("error: the edit was refused\n");
                return 1;
            }
            calls.push_back(timer.nsecsElapsed() / 1e6); // the GUI thread's own share: the new design and its panels
            while ((map->busy() || map->generation() == generation) && timer.elapsed() < 5000)
                QApplication::processEvents(QEventLoop::AllEvents, 1);
            map->repaint();
            times.push_back(timer.nsecsElapsed() / 1e6);
            if (map->busy() || map->area() == area) {
                std::printf("error: no new map after the edit (area %.1f mm²)\n", map->area());
                return 1;
            }
        }
        std::sort(times.begin(), times.end());
        std::sort(calls.begin(), calls.end());
        const double median = times[times.size() / 2], p95 = times[times.size() * 95 / 100];
        std::printf("the edit itself on the GUI thread (new design, panels, ghosts): median %.1f ms, max %.1f ms\n",
                    calls[calls.size() / 2], calls.back());
        std::printf("design edit (l1 +-1 %%) until the new %dx%d map of %s is on screen, %zu edits: median %.1f ms, "
                    "p95 %.1f ms, max %.1f ms, of which %d ms debounce (target <= %.1f ms)\n",
                    map->summary().grid.columns, map->summary().grid.rows, qPrintable(preset), times.size(), median, p95,
                    times.back(), pkm::WorkspaceMapView::debounceMilliseconds, limitMs);
        return median <= limitMs ? 0 : 1;
    }
    pkm::LinkageView3D *view3d = window.view3d()->view();
    if (in3d) {
        window.viewTabs()->setCurrentIndex(1);
        QApplication::processEvents();
        if (!view3d->isGlAvailable()) {
            std::printf("error: no OpenGL for the 3D view: %s\n", qPrintable(view3d->glStatus()));
            return 1;
        }
    }
    QApplication::processEvents();
    window.repaint();
    const pkm::Pose home = window.document()->pose();
    // The handle that moves the platform (attachment points edit the design instead).
    int platformHandle = 0;
    const pkm::Scene scene = window.document()->mechanism()->scene(home);
    for (int h = 0; h < static_cast<int>(scene.handles.size()); ++h) {
        if (!scene.handles[std::size_t(h)].editsDesign()) {
            platformHandle = h;
            break;
        }
    }
    // A loop that stays inside the workspace: 25 mm for MOMA, 4 % of the design's size
    // for a small one (the 3-RPR's struts are 12 to 30 mm).
    const double radius = std::min(25.0, 0.04 * scene.extent.sizes().head<2>().maxCoeff());
    const int framesBefore = view3d->frameCount();

    const int steps = 600;
    QElapsedTimer timer;
    const int paintsBefore = window.linkageView()->paintCount();
    const auto run = [&](std::vector<double> &times) {
        for (int i = 0; i < steps; ++i) {
            // θ from −60° to 60° and back, as a hand drags the slider
            const double u = (i % 200) / 199.0;
            const double thetaDeg = (i / 200) % 2 == 0 ? -60 + 120 * u : 60 - 120 * u;
            timer.start();
            if (platform) {
                // a loop about the start, as a hand drags the platform
                const double angle = 2 * 3.141592653589793 * i / 200.0;
                const Eigen::Vector2d target = home.outputs.head<2>() + radius * Eigen::Vector2d(std::cos(angle) - 1, std::sin(angle));
                window.document()->dragHandle(platformHandle, target);
            } else {
                window.document()->setVariable(window.document()->mechanism()->variableIndex("theta"), thetaDeg * pkm::units::degree);
            }
            // Deliver the pending paint requests now, as the event loop would before the next
            // input event: only what changed repaints, as on a real screen.
            QApplication::processEvents();
            if (in3d) {
                // the frame is done when the GL pipeline has drawn it
                view3d->finishFrame();
            }
            times.push_back(timer.nsecsElapsed() / 1e6);
        }
    };
    const auto medianOf = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    std::vector<double> times;
    times.reserve(steps);
    if (shapes) {
        // off and on in alternating rounds, so that a change of the machine's load meets both
        std::vector<double> off, on;
        for (int round = 0; round < 3; ++round) {
            window.setCapabilityShapes(false);
            run(off);
            window.setCapabilityShapes(true);
            run(on);
        }
        if (window.linkageView()->scene().legend.empty()) {
            std::printf("error: the shapes are not drawn\n");
            return 1;
        }
        const double added = medianOf(on) - medianOf(off);
        std::printf("velocity and force shapes: step median %.2f ms without, %.2f ms with: +%.3f ms (target <= 1.0 ms)\n",
                    medianOf(off), medianOf(on), added);
        if (added > 1.0)
            return 1;
        times = on;
    } else {
        run(times);
    }
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    const double p95 = times[times.size() * 95 / 100];
    const double worst = times.back();
    std::printf("%s%s + full repaint at 1920x1080 over %d steps: median %.2f ms, p95 %.2f ms, max %.2f ms "
                "(target <= %.1f ms)\n",
                platform ? "platform drag with the map visible" : "slider move", in3d ? ", 3D view shown," : "", steps,
                median, p95, worst, limitMs);
    if (in3d) {
        const int frames = view3d->frameCount() - framesBefore;
        std::printf("3D view: %d frames in %d steps, last frame %.3f ms\n", frames, steps, view3d->lastFrameMilliseconds());
        if (frames < steps) {
            std::printf("error: the 3D view did not draw on every step\n");
            return 1;
        }
        return p95 <= limitMs ? 0 : 1;
    }
    const int paints = window.linkageView()->paintCount() - paintsBefore;
    std::printf("linkage view: painted %d times in %d steps, last paint %.3f ms\n", paints, steps,
                window.linkageView()->lastPaintMilliseconds());
    // A step that did not repaint would make the figure meaningless.
    if (paints < int(times.size())) {
        std::printf("error: the view did not repaint on every step\n");
        return 1;
    }
    return p95 <= limitMs ? 0 : 1;
}
