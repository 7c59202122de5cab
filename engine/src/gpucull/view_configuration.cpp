// Algorithm 2 of the thesis: choosing views from the matrix, and updating it.

#include "gpucull/view_configuration.hpp"

#include <algorithm>
#include <cassert>

namespace collidescope::gpucull {

ViewConfiguration::ViewConfiguration(ViewConfigurationConfig config)
    : m_config(config), m_random(config.seed) {
    // Before any frame: z, then x, then y (the default order), by small distinct scores.
    for (auto& row : m_matrix) row = {0.02, 0.01, 0.03};
}

std::vector<int> ViewConfiguration::choose(int passes) {
    assert(passes >= 1 && passes <= 3);
    const int explored = m_config.explore ? static_cast<int>(m_random() % static_cast<unsigned>(passes)) : -1;
    std::vector<int> views;
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<int> unused;
        for (int view = 0; view < 3; ++view) {
            if (std::find(views.begin(), views.end(), view) == views.end()) unused.push_back(view);
        }
        if (pass == explored) {
            views.push_back(unused[m_random() % unused.size()]);
            continue;
        }
        // The best unused view; ties go to the lower axis, so choices are deterministic.
        const auto& row = m_matrix[static_cast<std::size_t>(pass)];
        views.push_back(*std::max_element(unused.begin(), unused.end(), [&](int a, int b) {
            return row[static_cast<std::size_t>(a)] < row[static_cast<std::size_t>(b)];
        }));
    }
    return views;
}

void ViewConfiguration::update(const std::vector<int>& views, const std::vector<double>& culled) {
    assert(views.size() == culled.size() && views.size() <= 3);
    for (std::size_t pass = 0; pass < views.size(); ++pass) {  // (4.1)
        double& entry = m_matrix[pass][static_cast<std::size_t>(views[pass])];
        entry = entry / 4 + 0.75 * culled[pass];
    }
    for (std::size_t pass = 1; pass < views.size(); ++pass) {  // step 2
        const auto view = static_cast<std::size_t>(views[pass]);
        m_matrix[0][view] = std::max(m_matrix[0][view], m_matrix[pass][view]);
    }
    for (auto& row : m_matrix) {  // (4.2)
        for (double& entry : row) entry *= m_config.decay_rate;
    }
}

std::vector<double> ViewConfiguration::culled_fractions(const GpuFrameInfo& info, std::size_t passes) {
    std::vector<double> culled;
    for (const GpuViewInfo& view : info.views) {
        if (view.level != 1) continue;
        culled.push_back(view.pcs_in == 0 ? 1.0 : 1.0 - static_cast<double>(view.pcs_out) / view.pcs_in);
    }
    culled.resize(passes, 1.0);
    return culled;
}

}  // namespace collidescope::gpucull
