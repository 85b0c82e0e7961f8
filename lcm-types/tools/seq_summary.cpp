#include "seq_summary.hpp"

#include <iterator>

namespace firtp::dump {
namespace {

constexpr int max_listed_gaps = 10;

// Adds seq to the runs; false when it was there already.
bool insert(std::map<std::int64_t, std::int64_t>& runs, std::int64_t seq) {
    auto next = runs.upper_bound(seq);  // first run starting after seq
    if (next != runs.begin()) {
        auto run = std::prev(next);
        if (seq <= run->second) return false;
        if (seq == run->second + 1) {
            run->second = seq;
            if (next != runs.end() && next->first == seq + 1) {
                run->second = next->second;
                runs.erase(next);
            }
            return true;
        }
    }
    if (next != runs.end() && next->first == seq + 1) {
        const std::int64_t last = next->second;
        runs.erase(next);
        runs.emplace(seq, last);
        return true;
    }
    runs.emplace(seq, seq);
    return true;
}

std::string range(std::int64_t first, std::int64_t last) {
    std::string text = std::to_string(first);
    if (last != first) text.append("-").append(std::to_string(last));
    return text;
}

}  // namespace

void SeqSummary::add(const std::string& channel, const EventText& event) {
    Channel& c = channels_[channel];
    ++c.events;
    if (event.corrupted) {
        ++c.corrupted;
        return;
    }
    const std::optional<SeqKey>& key = event.key;
    if (!key) {
        ++c.unknown;
        return;
    }
    if (key->config) {
        if (config_seen_ && key->seq <= config_seq_) ++run_;  // its publisher started again
        config_seen_ = true;
        config_seq_ = key->seq;
    }
    c.sessions = key->session;
    Stream& s = c.programs[{key->program == 0 ? run_ : 0, key->program}];
    const bool first = s.events++ == 0;
    if (!insert(s.runs, key->seq))
        ++s.repeated;
    else if (!first && key->seq < s.highest)
        ++s.reordered;
    if (first || key->seq > s.highest) s.highest = key->seq;
}

std::int64_t SeqSummary::Stream::missing() const {
    std::int64_t gaps = 0;
    for (auto run = runs.begin(); run != runs.end() && std::next(run) != runs.end(); ++run)
        gaps += std::next(run)->first - run->second - 1;
    return gaps;
}

std::map<std::string, ChannelTotals> SeqSummary::totals() const {
    std::map<std::string, ChannelTotals> out;
    for (const auto& [name, c] : channels_) {
        ChannelTotals& t = out[name];
        t.events = c.events;
        t.corrupted = c.corrupted;
        t.unknown = c.unknown;
        for (const auto& [program, s] : c.programs) {
            t.missing += s.missing();
            t.repeated += s.repeated;
            t.reordered += s.reordered;
        }
    }
    return out;
}

void SeqSummary::print(std::ostream& out) const {
    for (const auto& [name, c] : channels_) {
        if (c.unknown > 0) out << name << " events=" << c.unknown << " unknown type\n";
        if (c.corrupted > 0) out << name << " events=" << c.corrupted << " corrupted (CRC mismatch)\n";
        for (const auto& [key, s] : c.programs) {
            const auto& [run_index, program] = key;
            out << name;
            if (program != 0) out << (c.sessions ? " session=" : " program=") << program;
            if (run_ > 0 && program == 0) out << " run=" << run_index + 1;
            const std::int64_t first = s.runs.begin()->first;
            const std::int64_t missing = s.missing();
            std::string gaps;
            int listed = 0;
            for (auto run = s.runs.begin(); std::next(run) != s.runs.end(); ++run) {
                const std::int64_t from = run->second + 1, to = std::next(run)->first - 1;
                if (listed++ < max_listed_gaps) gaps.append(gaps.empty() ? "" : ",").append(range(from, to));
                else if (listed == max_listed_gaps + 1) gaps.append(",...");
            }
            out << " events=" << s.events << " seq=" << range(first, s.highest) << " missing=" << missing;
            if (!gaps.empty()) out << " gaps=" << gaps;
            out << " repeated=" << s.repeated << " reordered=" << s.reordered << "\n";
        }
    }
}

}  // namespace firtp::dump
