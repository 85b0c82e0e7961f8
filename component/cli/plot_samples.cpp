#include "plot_samples.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace firtp::cli {
namespace {

constexpr std::size_t max_zooms = 4;
constexpr std::size_t max_buckets = 4000;     // decimation buckets of the overview and time plots
constexpr std::size_t recent_samples = 16384; // looked back over when a corner is chosen for a zoom
constexpr std::size_t max_zoom_rows = 100000; // samples a zoom keeps
constexpr double min_zoom_window = 0.5;       // mm
constexpr double zoom_window_factor = 6.0;    // window = this x (tolerance or error)
constexpr double collinear_beta = 1e-6;       // rad: joined blocks, nothing to zoom on

// Every sample within 1.5 half widths of the corner; a blank (NaN) row where a run leaves it.
void capture(ZoomSamples& zoom, const Eigen::Vector2d& xy) {
    const double reach = 1.5 * zoom.half_width;
    const bool near = (xy - zoom.centre).cwiseAbs().maxCoeff() <= reach;
    if (zoom.xy.size() >= max_zoom_rows) return;
    if (near) zoom.xy.push_back(xy);
    else if (zoom.inside) zoom.xy.push_back(Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
    zoom.inside = near;
}

}  // namespace

double zoom_half_width(const CornerReport& c, double error) {
    const double tolerance = !c.exact_stop && std::isfinite(c.epsilon) ? c.epsilon : 0.0;
    return 0.5 * std::max(min_zoom_window, zoom_window_factor * std::max(tolerance, error));
}

bool zoomable(const CornerReport& c) { return c.beta > collinear_beta; }

PlotSamples::PlotSamples() : path(max_buckets), time(max_buckets) {}

void PlotSamples::add(const AxisState& s) {
    const Eigen::Vector2d xy = s.position.head<2>();
    const double feed = s.velocity.head<3>().norm();
    path.add({xy[0], xy[1]});
    time.add({s.time, feed, s.acceleration[0], s.acceleration[1], s.acceleration[2]});
    low = any ? Eigen::Vector2d(low.cwiseMin(xy)) : xy;
    high = any ? Eigen::Vector2d(high.cwiseMax(xy)) : xy;
    any = true;
    max_feed = std::max(max_feed, feed);
    max_acceleration = std::max(max_acceleration, s.acceleration.head<3>().cwiseAbs().maxCoeff());
    for (ZoomSamples& z : zooms) capture(z, xy);
    recent_.push_back(xy);
    if (recent_.size() > recent_samples) recent_.pop_front();
}

// The zooms are the (up to four) real corners with the largest errors, earlier ones first on ties.
void PlotSamples::corner_error(std::size_t index, double error, const CornerReport& report) {
    if (!zoomable(report)) return;
    if (zooms.size() == max_zooms) {
        auto smallest = zooms.begin();  // the latest of the smallest errors goes
        for (auto z = zooms.begin(); z != zooms.end(); ++z)
            if (z->error <= smallest->error) smallest = z;
        if (error <= smallest->error) return;
        zooms.erase(smallest);
    }
    ZoomSamples zoom{index, error, report.point.head<2>(), zoom_half_width(report, error), {}, false};
    for (const Eigen::Vector2d& xy : recent_) capture(zoom, xy);
    zooms.insert(std::upper_bound(zooms.begin(), zooms.end(), index,
                                  [](std::size_t i, const ZoomSamples& z) { return i < z.corner; }),
                 std::move(zoom));
}

}  // namespace firtp::cli
