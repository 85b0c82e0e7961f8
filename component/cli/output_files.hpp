// Output files written as temporaries beside their targets and renamed into place together once
// everything succeeded; temporaries not committed are removed when the object goes away.
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace firtp::cli {

class OutputFiles {
public:
    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    ~OutputFiles();

    // Creates an empty temporary ".NAME.XXXXXX" in the target's directory and returns its path
    // (through a symbolic link: the directory of the file it names). A target that exists and is
    // not a file (a device, a pipe) is returned itself, written in place. Throws
    // std::runtime_error naming the target when that fails.
    std::filesystem::path create(const std::filesystem::path& target);

    // create(), then lets `fill` write the temporary as text; throws naming the target unless every
    // byte reached the file.
    template <class Fill>
    void write(const std::filesystem::path& target, Fill&& fill) {
        std::ofstream out(create(target), std::ios::binary);
        fill(out);
        out.close();
        if (!out) throw std::runtime_error("cannot write '" + target.string() + "'");
    }

    // Renames every temporary onto its target.
    void commit();

private:
    struct Pending {
        std::filesystem::path temporary;
        std::filesystem::path target;
    };
    std::vector<Pending> pending_;
};

}  // namespace firtp::cli
