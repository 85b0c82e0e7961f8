// Per channel (and per program for blocks): how many events, which seq values, what is missing.
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
        std::map<std::int64_t, Stream> programs;     // program 0 for the types without one
    };
    std::map<std::string, Channel> channels_;
};

}  // namespace firtp::dump
