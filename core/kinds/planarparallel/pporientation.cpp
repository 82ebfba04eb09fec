// The orientation range of a 3-DOF planar parallel platform (docs/mathematics.md, "Planar
// parallel mechanisms from a leg library"): at a platform point (x, y) the angles φ at which
// every leg reaches its platform point P_i = (x, y) + R(φ)·B_i in its working mode and input
// range. A leg's reach is a union of arcs of φ, so the set is scanned and its ends refined.
#include "planarparallel.h"

#include <cmath>
#include <numbers>

namespace pkm {

namespace {
constexpr double pi = std::numbers::pi;
/// The scan: 120 steps of 3° over the full turn, each end then bisected to 3°/2²⁴.
constexpr int orientationSamples = 120;
constexpr int refinements = 24;
} // namespace

int PlanarParallel::orientationIntervals(const Eigen::Vector2d &xy, std::span<Interval> intervals, double *margin) const
{
    if (m_design.legCount() != 3 || intervals.empty())
        return 0;
    Coordinates q;
    auto holds = [&](double phi) {
        int culprit = 0;
        return inverseCheck(Eigen::Vector3d(xy.x(), xy.y(), phi), nullptr, q, culprit) == planar::Reach::Yes;
    };
    // the end between an angle that holds and one that does not, by bisection
    auto end = [&](double in, double out) {
        for (int k = 0; k < refinements; ++k) {
            const double middle = 0.5 * (in + out);
            (holds(middle) ? in : out) = middle;
        }
        return in;
    };
    const double step = 2.0 * pi / orientationSamples;
    std::array<bool, orientationSamples> held{};
    int count = 0;
    for (int k = 0; k < orientationSamples; ++k)
        count += (held[std::size_t(k)] = holds(-pi + k * step)) ? 1 : 0;
    int found = 0;
    if (count == orientationSamples) {
        intervals[0] = {-pi, pi};
        found = 1;
    } else if (count > 0) {
        // start the runs after a sample that does not hold, so that none is cut at ±π
        int first = 0;
        while (held[std::size_t(first)])
            ++first;
        for (int k = 1; k <= orientationSamples && found < int(intervals.size()); ++k) {
            const int at = (first + k) % orientationSamples;
            if (!held[std::size_t(at)])
                continue;
            int last = at;
            while (held[std::size_t((last + 1) % orientationSamples)])
                last = (last + 1) % orientationSamples;
            const double start = -pi + at * step;
            const double stop = -pi + (last >= at ? last : last + orientationSamples) * step;
            Interval run{end(start, start - step), end(stop, stop + step)};
            if (run.min < -pi) { // keep min in [−π, π)
                run.min += 2.0 * pi;
                run.max += 2.0 * pi;
            }
            intervals[std::size_t(found++)] = run;
            k += (last >= at ? last - at : last + orientationSamples - at);
        }
    }
    if (margin) {
        *margin = 0.0;
        int widest = -1;
        for (int k = 0; k < found; ++k) {
            if (widest < 0 || intervals[std::size_t(k)].max - intervals[std::size_t(k)].min
                                  > intervals[std::size_t(widest)].max - intervals[std::size_t(widest)].min)
                widest = k;
        }
        if (widest >= 0) {
            const Interval &w = intervals[std::size_t(widest)];
            const double phi = 0.5 * (w.min + w.max);
            if (holds(phi)) {
                Pose pose;
                pose.inputs = q;
                pose.outputs = Eigen::Vector3d(xy.x(), xy.y(), phi);
                *margin = singularity(pose).margin;
            }
        }
    }
    return found;
}

} // namespace pkm
