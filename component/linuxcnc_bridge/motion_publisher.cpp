#include "motion_publisher.hpp"

#include <hal.h>

#include <firtp/hal/hal_pin_access.hpp>

#include <stdexcept>
#include <string>

namespace firtp {

namespace {

// LinuxCNC 2.9's sampler creates channel N's stream with this key + N (src/hal/components/streamer.h).
constexpr int sampler_shmem_key = 0x48534130;

char type_letter(hal_type_t type) {
    switch (type) {
        case HAL_FLOAT: return 'f';
        case HAL_BIT: return 'b';
        case HAL_S32: return 's';
        case HAL_U32: return 'u';
        default: return '?';
    }
}

}  // namespace

std::string motion_sampler_cfg(int axes) { return std::string(static_cast<std::size_t>(axes), 'f') + "s"; }

struct MotionPublisher::Pins {
    hal_bit_t* enabled;       // in: motion.motion-enabled (machine on)
    hal_bit_t* in_position;   // in: motion.in-position
    hal_s32_t* queue_depth;   // in: the planner's queue, e.g. firtp_tp.depth (optional)
    hal_float_t* feed_scale;  // in: feed override in effect, e.g. halui.feed-override.value (optional, 1)
    hal_u32_t* states;        // out: axis states published
    hal_u32_t* lost;          // out: servo periods the sampler could not pass on (its stream was full)
};

struct MotionPublisher::Stream {
    hal_stream_t stream;
};

MotionPublisher::MotionPublisher(lcm::LCM& lcm, const MotionOptions& options) : lcm_(&lcm), options_(options) {
    if (options.axes < 1 || options.axes > max_axes || options.axes + 1 > HAL_STREAM_MAX_PINS)
        throw std::runtime_error("--axes " + std::to_string(options.axes) + ": must be 1 to 9");
    const char* name = options.name.c_str();
    comp_id_ = hal_init(name);
    if (comp_id_ < 0) throw std::runtime_error(options.name + ": hal_init failed (is a HAL session running?)");
    pins_ = static_cast<Pins*>(hal_malloc(sizeof(Pins)));
    int r = pins_ ? 0 : -1;
    r = r ? r : hal_pin_bit_newf(HAL_IN, &pins_->enabled, comp_id_, "%s.enabled", name);
    r = r ? r : hal_pin_bit_newf(HAL_IN, &pins_->in_position, comp_id_, "%s.in-position", name);
    r = r ? r : hal_pin_s32_newf(HAL_IN, &pins_->queue_depth, comp_id_, "%s.queue-depth", name);
    r = r ? r : hal_pin_float_newf(HAL_IN, &pins_->feed_scale, comp_id_, "%s.feed-scale", name);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &pins_->states, comp_id_, "%s.states", name);
    r = r ? r : hal_pin_u32_newf(HAL_OUT, &pins_->lost, comp_id_, "%s.lost", name);
    if (r != 0) {
        hal_exit(comp_id_);
        throw std::runtime_error(options.name + ": cannot create its pins");
    }
    *pins_->feed_scale = 1.0;
    *pins_->in_position = true;
    stream_ = new Stream;
    const std::string cfg = motion_sampler_cfg(options.axes);
    std::string why;
    if (hal_stream_attach(&stream_->stream, comp_id_, sampler_shmem_key + options.sampler_channel, nullptr) != 0) {
        why = "no sampler channel " + std::to_string(options.sampler_channel) + " (loadrt sampler depth=16000 cfg=" +
              cfg + " before loadusr)";
    } else {
        std::string found;
        for (int i = 0; i < hal_stream_element_count(&stream_->stream); ++i)
            found += type_letter(hal_stream_element_type(&stream_->stream, i));
        if (found != cfg) {
            hal_stream_detach(&stream_->stream);
            why = "sampler channel " + std::to_string(options.sampler_channel) + " has cfg=" + found + ", expected " +
                  cfg + " (the " + std::to_string(options.axes) + " axes' pos-cmd, then motion.program-line)";
        }
    }
    if (!why.empty()) {
        delete stream_;
        stream_ = nullptr;
        hal_exit(comp_id_);
        throw std::runtime_error(options.name + ": " + why);
    }
    hal_ready(comp_id_);
}

MotionPublisher::~MotionPublisher() {
    hal_stream_detach(&stream_->stream);
    delete stream_;
    hal_exit(comp_id_);
}

void MotionPublisher::publish_state(std::int64_t tick, std::int32_t line, const double* position) {
    firtp_lcm::axis_state_t m{};
    m.utime = messages::now_utime();
    m.tick = tick;
    m.time = static_cast<double>(tick) * options_.period;
    m.line = line;
    // Velocity and acceleration: backward differences of the sampled positions over the period
    // (zero until two, three consecutive samples exist).
    for (int a = 0; a < options_.axes; ++a) {
        const double v = history_ >= 1 ? (position[a] - previous_position_[a]) / options_.period : 0.0;
        m.position[a] = position[a];
        m.velocity[a] = v;
        m.acceleration[a] = history_ >= 2 ? (v - previous_velocity_[a]) / options_.period : 0.0;
        previous_position_[a] = position[a];
        previous_velocity_[a] = v;
    }
    history_ = history_ < 2 ? history_ + 1 : 2;
    m.seq = ++state_seq_;
    messages::publish(*lcm_, messages::axis_state_channel, m);
    messages::publish_live(*lcm_, m, options_.live_decimation);
    ++states_;
    hal_pin::set(pins_->states, static_cast<std::uint32_t>(states_));
    if (line != line_) status_due_ = true;
    line_ = line;
    if (++periods_since_status_ >= options_.status_every) status_due_ = true;
}

// Lost periods: LinuxCNC 2.9's hal_stream_write numbers only the records it wrote, and counts
// the ones it could not (a full stream) in hal_stream_num_overruns; hal_stream(3) says the number
// also rises on a failed write, so a jump in it counts too (and is not counted twice). A full
// stream loses the periods after its newest record, so the overruns found with the records present
// are placed after them: the ticks stay the servo periods, the count is exact.
void MotionPublisher::poll() {
    hal_stream_data record[HAL_STREAM_MAX_PINS];
    double position[max_axes] = {};
    const int present = hal_stream_depth(&stream_->stream);
    const std::int64_t overruns = hal_stream_num_overruns(&stream_->stream);
    std::int64_t jumps = 0;  // periods missing between sample numbers, this poll
    unsigned sample = 0;
    for (int i = 0; i < present && hal_stream_read(&stream_->stream, record, &sample) == 0; ++i) {
        std::int64_t tick = last_tick_ + 1;
        if (last_tick_ < 0) {
            tick = sample;  // the first record's number: the sampler's periods so far
        } else if (const std::uint32_t step = sample - last_sample_; step != 1) {
            jumps += step - 1;
            tick += step - 1;
            lose(step - 1);
        }
        last_sample_ = sample;
        last_tick_ = tick;
        for (int a = 0; a < options_.axes; ++a) position[a] = record[a].f;
        publish_state(tick, record[options_.axes].s, position);
    }
    if (const std::int64_t unplaced = overruns - overruns_seen_ - jumps; unplaced > 0) {
        last_tick_ += unplaced;
        lose(unplaced);
    }
    overruns_seen_ = overruns;
    if (motion_state() != last_state_) status_due_ = true;
    if (status_due_) publish_status();
}

void MotionPublisher::lose(std::int64_t periods) {
    lost_ += periods;
    history_ = 0;  // no differences across the gap
    hal_pin::set(pins_->lost, static_cast<std::uint32_t>(lost_));
    status_due_ = true;
}

// Machine off: disabled; in position: idle; otherwise moving.
std::int8_t MotionPublisher::motion_state() const {
    if (!hal_pin::get(pins_->enabled)) return firtp_lcm::status_t::DISABLED;
    return hal_pin::get(pins_->in_position) ? firtp_lcm::status_t::IDLE : firtp_lcm::status_t::MOVING;
}

void MotionPublisher::publish_status() {
    firtp_lcm::status_t s{};
    s.utime = messages::now_utime();
    s.seq = ++status_seq_;
    s.tick = last_tick_ < 0 ? 0 : last_tick_;
    s.program = 0;  // LinuxCNC's interpreter feeds the planner: no firtp blocks, no sequence
    s.next_seq = 0;
    s.queue_depth = hal_pin::get(pins_->queue_depth);
    s.queue_free = 0;
    s.current_line = line_;
    last_state_ = motion_state();
    s.state = last_state_;
    s.feed_scale = hal_pin::get(pins_->feed_scale);
    if (lost_ > 0) {
        s.error_code = firtp_lcm::status_t::ERROR_LOST_STATE;
        s.error_text = std::to_string(lost_) + " axis states lost: the sampler's stream was full (the bridge fell "
                       "behind the servo thread; raise loadrt sampler depth=)";
    }
    s.rejected = 0;
    s.corrupted = 0;
    messages::publish(*lcm_, messages::status_channel, s);
    periods_since_status_ = 0;
    status_due_ = false;
}

}  // namespace firtp
