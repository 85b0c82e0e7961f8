#include "output_files.hpp"

#include <firtp/text_cat.hpp>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

namespace firtp::cli {
namespace {

std::runtime_error failure(const std::filesystem::path& target, const std::string& reason) {
    return std::runtime_error(cat("cannot write '", target.string(), "': ", reason));
}

// mkstemp makes files 0600; give outputs the usual 0666 minus umask.
void ordinary_permissions(int fd) {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
}

}  // namespace

OutputFiles::~OutputFiles() {
    for (const Pending& p : pending_) {
        std::error_code ignored;
        std::filesystem::remove(p.temporary, ignored);
    }
}

std::filesystem::path OutputFiles::create(const std::filesystem::path& requested) {
    if (requested.filename().empty()) throw failure(requested, "not a file name");
    std::error_code absent;  // (not there yet: the usual case)
    const std::filesystem::file_status status = std::filesystem::status(requested, absent);
    // A device or a pipe (--csv /dev/null) is written in place: renaming onto it would replace it.
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
        if (std::filesystem::is_directory(status)) throw failure(requested, "is a directory");
        return requested;
    }
    // Through a symbolic link: beside the file it names, which is the one replaced.
    std::error_code error;
    const std::filesystem::path target = std::filesystem::is_symlink(std::filesystem::symlink_status(requested, absent))
                                             ? std::filesystem::weakly_canonical(requested, error)
                                             : requested;
    if (error) throw failure(requested, error.message());
    std::string name = (target.parent_path() / cat(".", target.filename().string(), ".XXXXXX")).string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) throw failure(target, std::strerror(errno));
    ordinary_permissions(fd);
    ::close(fd);
    pending_.push_back({name, target});
    return name;
}

void OutputFiles::commit() {
    while (!pending_.empty()) {
        const Pending& p = pending_.front();
        std::error_code error;
        std::filesystem::rename(p.temporary, p.target, error);
        if (error) throw failure(p.target, error.message());
        pending_.erase(pending_.begin());
    }
}

}  // namespace firtp::cli
