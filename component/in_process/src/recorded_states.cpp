#include <firtp/recorded_states.hpp>

#include <stdexcept>

namespace firtp {

std::vector<AxisState> samples_from_axis_states(const std::vector<firtp_lcm::axis_state_t>& states, double period) {
    // A block starts in the period before the first one that reports its line.
    std::size_t first = 0;
    while (first < states.size() && states[first].line == 0) ++first;
    if (first == states.size()) throw std::runtime_error("no axis state shows a moving block: nothing was recorded");
    if (first > 0) --first;

    std::vector<AxisState> samples;
    const std::int64_t tick0 = states[first].tick;
    for (std::size_t i = first; i < states.size(); ++i) {
        const firtp_lcm::axis_state_t& m = states[i];
        AxisState s;
        s.time = static_cast<double>(m.tick - tick0) * period;
        s.line = m.line;
        for (int a = 0; a < max_axes; ++a) {
            s.position[a] = m.position[a];
            s.velocity[a] = m.velocity[a];
            s.acceleration[a] = m.acceleration[a];
        }
        if (!samples.empty()) s.jerk = (s.acceleration - samples.back().acceleration) / period;
        samples.push_back(s);
    }
    // Keep one sample of the final rest.
    while (samples.size() > 1 && samples.back().position == samples[samples.size() - 2].position &&
           samples[samples.size() - 2].velocity.isZero() && samples[samples.size() - 2].line == 0)
        samples.pop_back();
    return samples;
}

}  // namespace firtp
