#include <firtp/planner.hpp>

#include <firtp/kernel.hpp>

#include <cmath>
#include <stdexcept>

namespace firtp {

namespace {

PlannerParameters checked(const PlannerParameters& p) {
    if (!(std::isfinite(p.period) && p.period > 0.0)) throw std::invalid_argument("the servo period must be positive and finite");
    if (p.queue_capacity < 2) throw std::invalid_argument("the queue must hold at least 2 blocks");
    if (const char* why = validate_rate(p); *why) throw std::invalid_argument(why);
    if (p.fixed_chain) {
        if (const char* why = validate(p.filters); *why) throw std::invalid_argument(why);
        if (const char* why = validate_window(p.filters, p.period); *why) throw std::invalid_argument(why);
    } else {
        bool any = false;
        for (int a = 0; a < p.limits.axes; ++a) {
            const double acc = p.limits.axis[a].max_acceleration;
            if (!(acc >= 0.0 && std::isfinite(acc))) throw std::invalid_argument("an acceleration limit is negative or not finite");
            any = any || acc > 0.0;
        }
        if (!any) throw std::invalid_argument("no axis has an acceleration limit (MAX_ACCELERATION): give them, or the filter times");
    }
    return p;
}

bool finite(const AxisVector& v) { return v.allFinite(); }

constexpr const char* absent_axis_names[max_axes] = {
    "moves X, an axis the machine does not have (no acceleration limit)", "moves Y, an axis the machine does not have (no acceleration limit)",
    "moves Z, an axis the machine does not have (no acceleration limit)", "moves A, an axis the machine does not have (no acceleration limit)",
    "moves B, an axis the machine does not have (no acceleration limit)", "moves C, an axis the machine does not have (no acceleration limit)",
    "moves U, an axis the machine does not have (no acceleration limit)", "moves V, an axis the machine does not have (no acceleration limit)",
    "moves W, an axis the machine does not have (no acceleration limit)"};

}  // namespace

Planner::Planner(const PlannerParameters& parameters, const AxisVector& start)
    : parameters_(checked(parameters)), chain_(parameters.fixed_chain ? FirChain(parameters.filters) : FirChain()),
      timeline_(parameters.period, 3 * parameters.queue_capacity + 16, start,
                parameters.fixed_chain ? chain_.delay() : 0.0,
                parameters.fixed_chain ? rate_limits(parameters) : RateLimits{}) {
    if (parameters_.fixed_chain) paper_ = std::make_unique<PaperPlanner>(parameters_, chain_, timeline_, start);
    else lookahead_ = std::make_unique<Lookahead>(parameters_, timeline_, start);
}

Planner::~Planner() = default;

Result Planner::add(const Block& block, Planning when) {
    const bool blend = block.termination == Termination::blend;
    if (!finite(block.target) || !std::isfinite(block.feed) || block.feed <= 0.0 || std::isnan(block.tolerance) ||
        (blend && !(block.tolerance > 0.0)) || !(block.dwell >= 0.0 && block.dwell <= max_dwell)) {
        refusal_ = "invalid block (non-finite target, feed <= 0, bad tolerance or dwell)";
        return Result::invalid_block;
    }
    if (aborting_) return Result::queue_full;
    const AxisVector& from = goal();
    if (!paper_)  // an axis without an acceleration limit is one the machine does not have
        for (int a = 0; a < max_axes; ++a)
            if (!(a < parameters_.limits.axes && parameters_.limits.axis[a].max_acceleration > 0.0) &&
                block.target[a] != from[a]) {
                refusal_ = absent_axis_names[a];
                return Result::absent_axis;
            }
    const Result r = paper_ ? paper_->add(block) : lookahead_->add(block, when);
    if (r == Result::ok) ++accepted_;
    if (r == Result::invalid_block) refusal_ = "invalid block";
    if (r == Result::infeasible)
        refusal_ = "no feed, down to a stop, keeps this block within its tolerance and the axis limits";
    return r;
}

Result Planner::update(const PlannerInput& in, PlannerOutput& out) noexcept {
    set_rate(in.hold ? 0.0 : in.rate);
    if (in.end_of_program) finish();
    tick(out.state);
    out.flushed = take_flushed();
    return idle() ? Result::finished : Result::working;
}

void Planner::finish() {
    if (lookahead_) lookahead_->finish();
}

void Planner::tick(AxisState& out) {
    if (lookahead_) lookahead_->commit();
    timeline_.tick(out);
    if (paper_) {
        if (timeline_.take_flushed()) {  // an abort came to rest: the planner starts again there
            paper_->reset(timeline_.rest_position());
            timeline_.set_rate(rate_);
            aborting_ = false;
            flushed_ = true;
        }
    } else if (aborting_ && lookahead_->at_rest()) {
        lookahead_->reset(timeline_.rest_position());
        lookahead_->set_rate(rate_);
        aborting_ = false;
        flushed_ = true;
    }
    if (flushed_) accepted_ = 0, finished_base_ = timeline_.blocks_retired();
}

void Planner::set_rate(double rate) {
    rate_ = rate >= 0.0 ? std::min(rate, parameters_.max_rate) : 0.0;
    if (aborting_) return;  // stopping; the rate applies afterwards
    if (paper_) timeline_.set_rate(rate_);
    else lookahead_->set_rate(rate_);
}

void Planner::abort() {
    if (idle()) {  // at rest already: flushed at once
        flushed_ = true;
        return;
    }
    aborting_ = true;
    if (paper_) {
        timeline_.set_rate(0.0);
        timeline_.abort();
    } else {
        lookahead_->set_rate(0.0);
    }
}

bool Planner::take_flushed() {
    const bool f = flushed_;
    flushed_ = false;
    return f;
}

void Planner::reset(const AxisVector& position) {
    timeline_.reset(position);
    if (paper_) timeline_.set_rate(rate_);
    accepted_ = 0;
    finished_base_ = timeline_.blocks_retired();
    if (paper_) paper_->reset(position);
    else lookahead_->reset(position);
    aborting_ = false;
    flushed_ = false;
}

Kernel Planner::brake_kernel(const AxisVector& velocity) const {
    return paper_ ? Kernel{0.0, 0.0, &chain_} : step_kernel(smoothing_limits(parameters_.limits), velocity);
}

AxisVector Planner::braking_rest(const AxisVector& position, const AxisVector& velocity) const {
    return position + velocity * (0.5 * brake_kernel(velocity).width());
}

void Planner::brake_from(const AxisVector& position, const AxisVector& velocity) {
    // A leg whose rising edge is already behind (sharp) and whose falling edge starts now: the
    // motion continues at `velocity` through `position` and stops through the kernel.
    const Kernel kernel = brake_kernel(velocity);
    const double half = 0.5 * kernel.width();
    reset(position);
    timeline_.snap_rate(1.0);  // the axes move at `velocity` now, whatever the override was
    Leg leg;
    leg.tv = half;
    leg.delta = velocity * half;
    leg.end = position + leg.delta;
    leg.rise_tick = timeline_.now();
    leg.rise_offset = 0.0;
    leg.fall = 0.0;
    leg.rising = Kernel{};  // sharp: full speed at once
    leg.falling = kernel;
    timeline_.widen(kernel.width());
    timeline_.push(leg);
    if (paper_) paper_->reset(leg.end);
    else lookahead_->reset(leg.end);
}

bool Planner::idle() const {
    return timeline_.idle() && (paper_ || lookahead_->empty());
}

std::size_t Planner::depth() const {
    return timeline_.size() + (lookahead_ ? lookahead_->depth() : 0);
}

std::size_t Planner::free() const {
    if (paper_) return timeline_.free();
    return std::min(lookahead_->free(), timeline_.free() / 3);
}

const AxisVector& Planner::goal() const { return paper_ ? paper_->goal() : lookahead_->goal(); }

const PlannerStats& Planner::stats() const { return paper_ ? paper_->stats() : lookahead_->stats(); }

bool Planner::take_report(CornerReport& report) {
    return paper_ ? paper_->take_report(report) : lookahead_->take_report(report);
}

}  // namespace firtp
