#include "record_config.hpp"

#include "cli_errors.hpp"
#include "plan_run.hpp"

#include <firtp/text_cat.hpp>
#include <firtp/version.hpp>

#include <stdlib.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace firtp::cli {
namespace {

constexpr char word_separator = '\n';

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error(cat("cannot read '", file.string(), "'"));
    return text.str();
}

std::vector<std::string> split_words(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream in(text);
    for (std::string word; std::getline(in, word, word_separator);) words.push_back(word);
    return words;
}

// A private directory holding the logged INI under its own name, removed when done.
class LoggedIni {
public:
    LoggedIni(const std::string& name, const std::string& text) {
        std::string pattern = (std::filesystem::temp_directory_path() / "firtp-replay-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary directory");
        dir_ = pattern;
        path_ = dir_ / std::filesystem::path(name).filename();
        std::ofstream out(path_, std::ios::binary);
        out << text;
        if (!out.flush()) throw std::runtime_error(cat("cannot write '", path_.string(), "'"));
    }
    ~LoggedIni() {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }
    LoggedIni(const LoggedIni&) = delete;
    LoggedIni& operator=(const LoggedIni&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path dir_, path_;
};

}  // namespace

InProcessSettings serve_component_settings(const MachineConfig& machine, int queue) {
    InProcessSettings settings;
    settings.plan_budget_us = static_cast<int>(machine.period * 1e6 * 0.5);  // half the servo period
    settings.queue = queue;
    return settings;
}

firtp_lcm::config_t config_message(const std::string& command, std::span<const std::string> args,
                                   const ComponentOptions& options, const MachineConfig& machine,
                                   const InProcessSettings& settings) {
    firtp_lcm::config_t m{};
    m.sender = cat("firtp ", firtp::version);
    m.command = command;
    if (options.plan.ini) {
        m.ini_file = options.plan.ini->string();
        m.ini_text = read_text(*options.plan.ini);
    }
    for (const std::string& word : args) {
        if (word.find(word_separator) != std::string::npos)
            throw UsageError(cat("an argument with a line break cannot be logged: '", word, "'"));
        m.args.append(m.args.empty() ? "" : "\n").append(word);
    }
    m.queue = settings.queue;
    m.max_blocks = settings.max_blocks;
    m.stream_depth = settings.stream_depth;
    m.plan_budget_us = settings.plan_budget_us;
    m.period = machine.period;
    m.axes = machine.limits.axes;
    return m;
}

namespace {

// firtp.so's logged loadrt words (config_t "loadrt"): each NAME=VALUE, none of the settings that
// have their own fields (or the stream keys, which are the bridge's).
ModuleMachine loaded_machine(const firtp_lcm::config_t& config, const std::vector<std::string>& words) {
    static const std::set<std::string> not_words{"queue", "max_blocks", "plan_budget_us", "stream_depth", "block_key",
                                                 "state_key"};
    ModuleMachine m;
    m.axes = config.axes;
    m.period = config.period;
    for (const std::string& word : words) {
        const std::size_t equals = word.find('=');
        if (equals == 0 || equals == std::string::npos || not_words.count(word.substr(0, equals)))
            throw std::runtime_error(cat("FIRTP_CONFIG from ", config.sender, ": '", word,
                                         "' is not one of firtp.so's machine settings NAME=VALUE"));
    }
    if (m.axes < 1 || m.axes > max_axes || !(m.period > 0.0))
        throw std::runtime_error(cat("FIRTP_CONFIG from ", config.sender, ": axes ", std::to_string(config.axes),
                                     ", period ", std::to_string(config.period), " s: not a firtp.so machine"));
    m.arguments = words;
    return m;
}

}  // namespace

LoggedComponent component_from(const firtp_lcm::config_t& config) {
    const std::vector<std::string> args = split_words(config.args);
    LoggedComponent c;
    if (config.command == "loadrt") {
        c.machine = loaded_machine(config, args);
    } else {
        ComponentOptions options;
        if (config.command == "serve") options = parse_serve_options(args);
        else if (config.command == "run") options = parse_run_options(args);
        else throw std::runtime_error(cat("FIRTP_CONFIG from an unknown command '", config.command, "'"));
        std::optional<LoggedIni> ini;
        if (!config.ini_file.empty()) {
            ini.emplace(config.ini_file, config.ini_text);
            options.plan.ini = ini->path();
        } else {
            options.plan.ini.reset();
        }
        try {
            c.machine = module_machine(load_machine_config(options.plan));
        } catch (const std::exception& e) {
            throw std::runtime_error(cat("the logged machine (", config.ini_file.empty() ? "built-in" : config.ini_file,
                                         ") does not load: ", e.what()));
        }
    }
    c.settings.queue = config.queue;
    c.settings.max_blocks = config.max_blocks;
    c.settings.stream_depth = config.stream_depth;
    c.settings.plan_budget_us = config.plan_budget_us;
    const bool loaded = config.command == "loadrt";
    c.description = loaded ? cat(config.sender, ": firtp.so in LinuxCNC (",
                                 config.ini_file.empty() ? std::string("INI not logged") : config.ini_file, "), loadrt firtp")
                           : cat(config.sender, ": ", config.command, ", ",
                                 config.ini_file.empty() ? std::string("built-in machine") : config.ini_file,
                                 args.empty() ? "" : ", args");
    for (const std::string& word : args) c.description.append(" ").append(word);
    return c;
}

}  // namespace firtp::cli
