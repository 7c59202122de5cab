// bench's plots: time per frame per method on one scene, as a self-contained SVG line chart
// (the thesis's Figures 5.6-5.13 plot the same thing). No plotting library: the output is
// deterministic text, viewable in any browser and embeddable in Markdown.

#include "bench_report.hpp"

#include "collidescope/stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>
#include <sstream>

namespace collidescope::app {
namespace {

constexpr double k_width = 760;
constexpr double k_height = 420;
constexpr double k_left = 70;     // room for the y tick labels
constexpr double k_right = 150;   // room for the legend
constexpr double k_top = 40;
constexpr double k_bottom = 80;   // tick labels, then a mode strip per adaptive method
constexpr const char* k_palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                     "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `ticks` intervals.
double nice_step(double range, int ticks) {
    if (range <= 0) return 1;
    const double raw = range / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double factor : {1.0, 2.0, 5.0}) {
        if (factor * power >= raw) return factor * power;
    }
    return 10 * power;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// Data ranges: frames x0..x1; time 0..y1 (linear) or y0..y1 in decades (logarithmic, when
// the methods differ by more than 30x, so the fast ones do not vanish on the zero line).
struct Axes {
    double x0, x1, y0, y1;
    bool log;
    double px(double x) const { return k_left + (x1 > x0 ? (x - x0) / (x1 - x0) : 0.5) * (k_width - k_left - k_right); }
    double py(double y) const {
        const double t = log ? (std::log10(std::max(y, y0)) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)) : y / y1;
        return k_height - k_bottom - t * (k_height - k_top - k_bottom);
    }
    std::vector<double> y_ticks(double step) const {
        std::vector<double> ticks;
        if (log) {
            for (double y = y0; y <= y1 * 1.0001; y *= 10) ticks.push_back(y);
        } else {
            for (double y = 0; y <= y1 * (1 + 1e-9); y += step) ticks.push_back(y);
        }
        return ticks;
    }
};

void draw_axes(std::ostringstream& svg, const Axes& axes, double y_step, double x_step) {
    svg << "<g font-size=\"12\" fill=\"#333\">\n";
    for (const double y : axes.y_ticks(y_step)) {
        svg << "<line x1=\"" << k_left << "\" x2=\"" << k_width - k_right << "\" y1=\"" << axes.py(y)
            << "\" y2=\"" << axes.py(y) << "\" stroke=\"#ddd\"/>\n<text x=\"" << k_left - 6 << "\" y=\""
            << axes.py(y) + 4 << "\" text-anchor=\"end\">" << number(y) << "</text>\n";
    }
    for (double x = std::ceil(axes.x0 / x_step) * x_step; x <= axes.x1; x += x_step) {
        svg << "<text x=\"" << axes.px(x) << "\" y=\"" << k_height - k_bottom + 18
            << "\" text-anchor=\"middle\">" << number(x) << "</text>\n";
    }
    svg << "<line x1=\"" << k_left << "\" x2=\"" << k_left << "\" y1=\"" << k_top << "\" y2=\""
        << k_height - k_bottom << "\" stroke=\"#333\"/>\n<line x1=\"" << k_left << "\" x2=\""
        << k_width - k_right << "\" y1=\"" << k_height - k_bottom << "\" y2=\"" << k_height - k_bottom
        << "\" stroke=\"#333\"/>\n<text x=\"" << (k_left + k_width - k_right) / 2 << "\" y=\""
        << k_height - 12 << "\" text-anchor=\"middle\">frame</text>\n<text transform=\"translate(16,"
        << (k_top + k_height - k_bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">time per frame (ms"
        << (axes.log ? ", log scale" : "") << ")</text>\n</g>\n";
}

void draw_series(std::ostringstream& svg, const Axes& axes, const BenchScene& scene) {
    for (std::size_t m = 0; m < scene.methods.size(); ++m) {
        const char* colour = k_palette[m % std::size(k_palette)];
        svg << "<polyline fill=\"none\" stroke-width=\"1.8\" stroke=\"" << colour << "\" points=\"";
        for (const BenchFrame& frame : scene.frames) {
            if (frame.method != scene.methods[m]) continue;
            svg << axes.px(frame.frame) << ',' << axes.py(frame.total_ms()) << ' ';
        }
        const double legend_y = k_top + 10 + 20.0 * static_cast<double>(m);
        svg << "\"/>\n<line x1=\"" << k_width - k_right + 12 << "\" x2=\"" << k_width - k_right + 36
            << "\" y1=\"" << legend_y << "\" y2=\"" << legend_y << "\" stroke-width=\"3\" stroke=\""
            << colour << "\"/>\n<text x=\"" << k_width - k_right + 42 << "\" y=\"" << legend_y + 4
            << "\" font-size=\"13\">" << scene.methods[m] << "</text>\n";
    }
}

// Below the axis, one strip per adaptive method: the mode in force on each frame (Mode 1
// AABB blue, the hybrid framework green, Mode 2 GPU orange), like the thesis's figures mark it.
void draw_mode_strips(std::ostringstream& svg, const Axes& axes, const BenchScene& scene) {
    int strip = 0;
    const double half = axes.x1 > axes.x0 ? 0.5 * (axes.px(axes.x0 + 1) - axes.px(axes.x0)) : 2.0;
    for (const std::string& method : scene.methods) {
        if (!is_adaptive_method(method)) continue;
        const double y = k_height - k_bottom + 26 + 9.0 * strip++;
        for (const BenchFrame& frame : scene.frames) {
            if (frame.method != method || frame.mode == 0) continue;
            const char* colour = frame.mode == 2 ? "#fd8d3c" : frame.action == k_action_hybrid ? "#74c476" : "#9ecae1";
            svg << "<rect x=\"" << axes.px(frame.frame) - half << "\" y=\"" << y << "\" width=\"" << 2 * half
                << "\" height=\"7\" fill=\"" << colour << "\"/>\n";
        }
        svg << "<text x=\"" << k_width - k_right + 6 << "\" y=\"" << y + 7 << "\" font-size=\"10\">mode: " << method
            << "</text>\n";
    }
    if (strip > 0) {  // the strips' key, under the legend
        const double y = k_top + 20.0 * static_cast<double>(scene.methods.size()) + 16;
        const std::pair<const char*, const char*> keys[] = {
            {"#9ecae1", "Mode 1 (AABB)"}, {"#74c476", "hybrid"}, {"#fd8d3c", "Mode 2 (GPU)"}};
        for (std::size_t k = 0; k < std::size(keys); ++k) {
            const double key_y = y + 14.0 * static_cast<double>(k);
            svg << "<rect x=\"" << k_width - k_right + 12 << "\" y=\"" << key_y << "\" width=\"24\" height=\"7\" fill=\""
                << keys[k].first << "\"/>\n<text x=\"" << k_width - k_right + 42 << "\" y=\"" << key_y + 7
                << "\" font-size=\"10\">" << keys[k].second << "</text>\n";
        }
    }
}

}  // namespace

std::string plot_svg(const BenchScene& scene) {
    double x0 = 0, x1 = 0, y_max = 0, y_min = std::numeric_limits<double>::infinity();
    if (!scene.frames.empty()) x0 = x1 = scene.frames.front().frame;
    for (const BenchFrame& frame : scene.frames) {
        x0 = std::min<double>(x0, frame.frame);
        x1 = std::max<double>(x1, frame.frame);
        y_max = std::max(y_max, frame.total_ms());
        if (frame.total_ms() > 0) y_min = std::min(y_min, frame.total_ms());
    }
    const double y_step = nice_step(y_max, 5);
    const bool log = y_max > 0 && y_min < y_max / 30;
    const Axes axes{x0, x1, log ? std::pow(10.0, std::floor(std::log10(y_min))) : 0,
                    log ? std::pow(10.0, std::ceil(std::log10(y_max))) : std::max(y_step, std::ceil(y_max / y_step) * y_step),
                    log};

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << k_width << "\" height=\"" << k_height
        << "\" viewBox=\"0 0 " << k_width << ' ' << k_height << "\" font-family=\"sans-serif\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << k_left << "\" y=\"24\" "
        << "font-size=\"15\">Data set " << scene.name << " (" << scene.preset << ", " << scene.triangles
        << " triangles): time per frame</text>\n";
    draw_axes(svg, axes, y_step, nice_step(x1 - x0, 8));
    draw_series(svg, axes, scene);
    draw_mode_strips(svg, axes, scene);
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace collidescope::app
