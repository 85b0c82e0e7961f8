#include "record_file.hpp"

#include <firtp/text_cat.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <stdlib.h>
#include <unistd.h>

namespace firtp::cli {
namespace {

std::runtime_error file_error(const char* what, const char* doing, int error) {
    return std::runtime_error(cat("the temporary file of ", what, " (in TMPDIR, else /tmp): ", doing, ": ", std::strerror(error)));
}

}  // namespace

UnnamedFile::UnnamedFile(const char* what) : what_(what) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
    if (ec) throw file_error(what_, "no temporary directory", ec.value());
    std::string name = (dir / "firtp-XXXXXX").string();
    fd_ = ::mkstemp(name.data());
    if (fd_ < 0) throw file_error(what_, "cannot create it", errno);
    ::unlink(name.c_str());  // unnamed from now on: nothing is left behind
}

UnnamedFile::~UnnamedFile() { ::close(fd_); }

void UnnamedFile::append(const void* data, std::size_t bytes) {
    const char* from = static_cast<const char*>(data);
    while (bytes > 0) {
        if (filled_ == pending_.size()) flush();
        const std::size_t n = std::min(bytes, pending_.size() - filled_);
        std::memcpy(pending_.data() + filled_, from, n);
        filled_ += n, from += n, bytes -= n;
    }
}

void UnnamedFile::flush() {
    for (std::size_t done = 0; done < filled_;) {
        const ssize_t n = ::write(fd_, pending_.data() + done, filled_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw file_error(what_, "cannot write it", n < 0 ? errno : EIO);
        done += static_cast<std::size_t>(n);
    }
    filled_ = 0;
}

void UnnamedFile::read(void* data, std::size_t bytes, std::size_t offset) const {
    for (std::size_t got = 0; got < bytes;) {
        const ssize_t n = ::pread(fd_, static_cast<char*>(data) + got, bytes - got, static_cast<off_t>(offset + got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw file_error(what_, "cannot read it back", n < 0 ? errno : EIO);
        got += static_cast<std::size_t>(n);
    }
}

}  // namespace firtp::cli
