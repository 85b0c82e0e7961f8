// Per channel (and per program for blocks, per session for controls): how many events, which seq
// values, what is missing. A FIRTP_CONFIG whose seq is not above the last one's starts a new run of
// the component (it was started again): the channels without a program count anew from there.
#pragma once

#include "event_text.hpp"

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <utility>

namespace firtp::dump {

// What a channel's counters say, all its programs together.
struct ChannelTotals {
    std::int64_t events = 0;
    std::int64_t missing = 0;    // seq values never seen between the lowest and the highest seen
    std::int64_t repeated = 0;   // seq values seen more than once
    std::int64_t reordered = 0;  // a new seq below the highest seen
    std::int64_t corrupted = 0;  // crc did not match
    std::int64_t unknown = 0;    // no firtp_lcm type
};

class SeqSummary {
public:
    void add(const std::string& channel, const EventText& event);
    void print(std::ostream& out) const;
    std::map<std::string, ChannelTotals> totals() const;
    int restarts() const { return run_; }  // of the component, by its FIRTP_CONFIG seq

private:
    struct Stream {
        std::int64_t events = 0;
        std::int64_t repeated = 0;                   // seq seen before
        std::int64_t reordered = 0;                  // new seq below the highest seen
        std::int64_t highest = 0;
        std::map<std::int64_t, std::int64_t> runs;   // seen seq as [first, last] runs
        std::int64_t missing() const;
    };
    struct Channel {
        std::int64_t events = 0;
        std::int64_t unknown = 0;                    // events of no firtp_lcm type
        std::int64_t corrupted = 0;                  // firtp_lcm messages whose crc does not match
        // (run, program): program 0 for the types without one, counted per run; run 0 for the others
        std::map<std::pair<int, std::int64_t>, Stream> programs;
        bool sessions = false;                       // programs are control sessions
    };
    std::map<std::string, Channel> channels_;
    int run_ = 0;                                    // runs of the component before this one
    bool config_seen_ = false;
    std::int64_t config_seq_ = 0;                    // the last FIRTP_CONFIG's
};

}  // namespace firtp::dump
