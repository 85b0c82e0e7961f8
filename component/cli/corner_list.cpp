#include "corner_list.hpp"

namespace firtp::cli {

void CornerList::spool() {
    report_file_ = std::make_unique<RecordFile<Record>>("the corner reports");
    error_file_ = std::make_unique<RecordFile<double>>("the corner errors");
}

void CornerList::push_back(const CornerReport& report) {
    if (report_file_) report_file_->push_back(record_of(report));
    else reports_.push_back(report);
}

std::size_t CornerList::size() const { return report_file_ ? report_file_->size() : reports_.size(); }

CornerReport CornerList::operator[](std::size_t i) const {
    return report_file_ ? report_of((*report_file_)[i]) : reports_[i];
}

void CornerList::add_error(double error) {
    if (error_file_) error_file_->push_back(error);
    else errors_.push_back(error);
}

void CornerList::clear_errors() {
    errors_.clear();
    if (error_file_) error_file_ = std::make_unique<RecordFile<double>>("the corner errors");
    paired_ = false;
}

std::size_t CornerList::errors_count() const { return error_file_ ? error_file_->size() : errors_.size(); }

std::optional<double> CornerList::error(std::size_t i) const {
    if (!paired_) return std::nullopt;
    return error_file_ ? (*error_file_)[i] : errors_[i];
}

CornerList::Record CornerList::record_of(const CornerReport& c) {
    Record r{};
    r.line = c.line;
    for (Eigen::Index a = 0; a < max_axes; ++a) r.point[a] = c.point[a];
    r.beta = c.beta;
    r.speed_in = c.speed_in;
    r.speed_out = c.speed_out;
    r.epsilon = c.epsilon;
    r.predicted_error = c.predicted_error;
    r.Tk = c.Tk;
    r.Tk_tolerance = c.Tk_tolerance;
    r.exact_stop = c.exact_stop ? 1 : 0;
    r.bound = static_cast<std::int32_t>(c.bound);
    r.axis = c.axis;
    return r;
}

CornerReport CornerList::report_of(const Record& r) {
    CornerReport c;
    c.line = r.line;
    for (Eigen::Index a = 0; a < max_axes; ++a) c.point[a] = r.point[a];
    c.beta = r.beta;
    c.speed_in = r.speed_in;
    c.speed_out = r.speed_out;
    c.epsilon = r.epsilon;
    c.predicted_error = r.predicted_error;
    c.Tk = r.Tk;
    c.Tk_tolerance = r.Tk_tolerance;
    c.exact_stop = r.exact_stop != 0;
    c.bound = static_cast<CornerBound>(r.bound);
    c.axis = r.axis;
    return c;
}

}  // namespace firtp::cli
