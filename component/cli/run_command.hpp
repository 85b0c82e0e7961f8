// firtp run / serve / host: the chain G-code -> blocks -> LCM -> component -> axis state -> LCM.
#pragma once

#include <span>
#include <string>

namespace firtp::cli {

int run_command(std::span<const std::string> args);    // everything in this process, deterministic
int serve_command(std::span<const std::string> args);  // component + bridge, real-time servo thread
int host_command(std::span<const std::string> args);   // the host stub, against `firtp serve`

}  // namespace firtp::cli
