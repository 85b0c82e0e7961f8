// firtp record / replay: a lossless LCM log of a run, and the component run again on it.
#pragma once

#include <span>
#include <string>

namespace firtp::cli {

int record_command(std::span<const std::string> args);  // every message into an LCM log, seq checked
int replay_command(std::span<const std::string> args);  // the logged blocks through the component again

}  // namespace firtp::cli
