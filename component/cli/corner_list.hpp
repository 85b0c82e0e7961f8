// The corner reports of a plan and their measured errors, by index: in memory, or (spool()) in
// unnamed temporary files, 152 + 8 bytes a corner on disk and a small cache in memory, so that the
// summary, JSON report and checks of `firtp plan` read them back in order after the plan.
#pragma once

#include "record_file.hpp"

#include <firtp/report.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace firtp::cli {

class CornerList {
public:
    void spool();  // before the first push_back: from then on to temporary files

    void push_back(const CornerReport& report);
    std::size_t size() const;
    bool empty() const { return size() == 0; }
    CornerReport operator[](std::size_t i) const;
    // In order, by value (a loop's `const CornerReport&` binds to a copy).
    class Iterator {
    public:
        Iterator(const CornerList& list, std::size_t i) : list_(&list), i_(i) {}
        CornerReport operator*() const { return (*list_)[i_]; }
        Iterator& operator++() { ++i_; return *this; }
        bool operator!=(const Iterator& o) const { return i_ != o.i_; }

    private:
        const CornerList* list_;
        std::size_t i_;
    };
    Iterator begin() const { return {*this, 0}; }
    Iterator end() const { return {*this, size()}; }

    // Measured errors arrive in index order; they pair with the reports only when both counts agree
    // (pair_errors(), after the plan: interior points and corners are the same junctions then).
    void add_error(double error);
    void pair_errors() { paired_ = errors_count() == size(); }
    bool paired() const { return paired_; }
    std::size_t errors_count() const;
    void clear_errors();  // a new measurement
    std::optional<double> error(std::size_t i) const;

private:
    // CornerReport's fields in a fixed layout (its AxisVector is not trivially copyable).
    struct Record {
        std::int64_t line;
        double point[max_axes];
        double beta, speed_in, speed_out, epsilon, predicted_error, Tk, Tk_tolerance;
        std::int32_t exact_stop, bound, axis;
    };
    static Record record_of(const CornerReport& c);
    static CornerReport report_of(const Record& r);

    std::vector<CornerReport> reports_;
    std::vector<double> errors_;
    std::unique_ptr<RecordFile<Record>> report_file_;
    std::unique_ptr<RecordFile<double>> error_file_;
    bool paired_ = false;
};

}  // namespace firtp::cli
