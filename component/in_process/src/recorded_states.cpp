#include <firtp/recorded_states.hpp>

#include <stdexcept>
#include <utility>

namespace firtp {
namespace {

// Only the rest after a motion that stopped with no line is dropped at the end: a sample that
// stays where the one before stood still and idle.
bool rests_after(const AxisState& before, const AxisState& s) {
    return s.position == before.position && before.velocity.isZero() && before.line == 0;
}

bool same_but_time(const AxisState& a, const AxisState& b) {
    return a.line == b.line && a.position == b.position && a.velocity == b.velocity &&
           a.acceleration == b.acceleration && a.jerk == b.jerk;
}

}  // namespace

AxisStateSamples::AxisStateSamples(double period, std::function<void(const AxisState&)> out)
    : period_(period), out_(std::move(out)) {}

void AxisStateSamples::add(const firtp_lcm::axis_state_t& m) {
    // A block starts in the period before the first one that reports its line.
    if (!started_) {
        if (m.line == 0) {
            before_ = m;
            return;
        }
        started_ = true;
        tick0_ = before_ ? before_->tick : m.tick;
        if (before_) add(*before_);
        before_.reset();
    }
    AxisState s;
    s.line = m.line;
    for (int a = 0; a < max_axes; ++a) {
        s.position[a] = m.position[a];
        s.velocity[a] = m.velocity[a];
        s.acceleration[a] = m.acceleration[a];
    }
    if (previous_) s.jerk = (s.acceleration - previous_->acceleration) / period_;
    s.time = time_of(m.tick);
    take(m.tick, s);
}

void AxisStateSamples::take(std::int64_t tick, const AxisState& s) {
    const bool first = !previous_;
    const bool rests = previous_ && rests_after(*previous_, s);
    previous_ = s;
    if (first || !rests) {  // kept whatever follows: so is everything held before it
        release_held();
        return emit(s);
    }
    if (!held_.empty()) {
        Run& last = held_.back();
        if (same_but_time(last.sample, s) && tick == last.tick + static_cast<std::int64_t>(last.repeats) + 1) {
            ++last.repeats;
            return;
        }
    }
    held_.push_back({tick, s, 0});
}

void AxisStateSamples::release_held() {
    for (const Run& run : held_) {
        emit(run.sample);
        AxisState repeat = run.sample;
        for (std::size_t i = 1; i <= run.repeats; ++i) {
            repeat.time = time_of(run.tick + static_cast<std::int64_t>(i));
            emit(repeat);
        }
    }
    held_.clear();
}

void AxisStateSamples::emit(const AxisState& s) {
    out_(s);
    ++count_;
}

void AxisStateSamples::finish() {
    if (!started_) throw std::runtime_error("no axis state shows a moving block: nothing was recorded");
    held_.clear();  // the final rest: its first sample went out already
}

void AxisStateSamples::finish_at_rest() {
    if (started_) return finish();
    if (!before_) throw std::runtime_error("no axis state came: nothing was recorded");
    tick0_ = before_->tick;
    AxisState s;
    for (int a = 0; a < max_axes; ++a) s.position[a] = before_->position[a];
    emit(s);
}

std::vector<AxisState> samples_from_axis_states(const std::vector<firtp_lcm::axis_state_t>& states, double period) {
    std::vector<AxisState> samples;
    AxisStateSamples stream(period, [&](const AxisState& s) { samples.push_back(s); });
    for (const firtp_lcm::axis_state_t& m : states) stream.add(m);
    stream.finish();
    return samples;
}

}  // namespace firtp
