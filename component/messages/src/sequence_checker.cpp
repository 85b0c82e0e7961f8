// Exactly-once, in-order acceptance of (program, seq).
#include <firtp/messages.hpp>

namespace firtp::messages {

SequenceChecker::Verdict SequenceChecker::check(std::int64_t program, std::int64_t seq, bool new_program_allowed) const {
    std::int64_t expected = next_seq_;
    if (program < program_) return Verdict::repeated;  // a late copy from an earlier program
    if (program != program_) {
        if (!new_program_allowed) return Verdict::busy;
        expected = 1;  // a new program starts over
    }
    if (seq == expected) return Verdict::accept;
    return seq < expected ? Verdict::repeated : Verdict::gap;
}

void SequenceChecker::accepted(std::int64_t program, std::int64_t seq) {
    program_ = program;
    next_seq_ = seq + 1;
}

const char* SequenceChecker::describe(Verdict verdict) {
    switch (verdict) {
        case Verdict::accept: return "accepted";
        case Verdict::repeated: return "repeated: this seq was already accepted";
        case Verdict::gap: return "sequence gap: an earlier seq is missing, resend from next_seq";
        case Verdict::busy: return "busy: a new program while the previous one still has blocks queued";
    }
    return "unknown verdict";
}

}  // namespace firtp::messages
