// Fixed-size records of a trivially copyable type in an unnamed temporary file (TMPDIR, gone when
// the process ends however it ends): appended in order, read back by index through a small cache,
// so reading them in order costs one read per few hundred. Memory: the cache, not the count.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

namespace firtp::cli {

// The file itself: create, append (buffered), read at an offset (after flush()). Throws
// std::runtime_error naming `what`.
class UnnamedFile {
public:
    explicit UnnamedFile(const char* what);
    ~UnnamedFile();
    UnnamedFile(const UnnamedFile&) = delete;
    UnnamedFile& operator=(const UnnamedFile&) = delete;

    void append(const void* data, std::size_t bytes);
    void read(void* data, std::size_t bytes, std::size_t offset) const;
    void flush();

private:
    int fd_ = -1;
    const char* what_;
    std::array<char, 1 << 16> pending_{};  // written in 64 KiB pieces
    std::size_t filled_ = 0;
};

template <class R>
class RecordFile {
    static_assert(std::is_trivially_copyable_v<R>);

public:
    explicit RecordFile(const char* what) : file_(what) {}
    void push_back(const R& r) {
        file_.append(&r, sizeof r);
        ++size_;
        first_ = size_;  // the cache may be stale now
    }
    std::size_t size() const { return size_; }
    R operator[](std::size_t i) const {
        if (i < first_ || i >= first_ + cached_) {
            file_.flush();
            first_ = i - i % cache_.size();
            cached_ = std::min(cache_.size(), size_ - first_);
            file_.read(cache_.data(), cached_ * sizeof(R), first_ * sizeof(R));
        }
        return cache_[i - first_];
    }

private:
    mutable UnnamedFile file_;  // reading flushes what is pending first
    std::size_t size_ = 0;
    mutable std::array<R, 256> cache_{};
    mutable std::size_t first_ = 0, cached_ = 0;
};

}  // namespace firtp::cli
