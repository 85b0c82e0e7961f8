#include "record_config.hpp"

#include "cli_errors.hpp"
#include "plan_run.hpp"

#include <firtp/text_cat.hpp>
#include <firtp/version.hpp>

#include <stdlib.h>

#include <fstream>
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

ConfigPublisher::ConfigPublisher(lcm::LCM& lcm, firtp_lcm::config_t message, std::chrono::milliseconds every)
    : lcm_(&lcm), message_(std::move(message)), every_(every) {
    publish();
}

void ConfigPublisher::poll() {
    if (std::chrono::steady_clock::now() - last_ >= every_) publish();
}

void ConfigPublisher::publish() {
    ++message_.seq;
    message_.utime = messages::now_utime();
    messages::publish(*lcm_, messages::config_channel, message_);
    last_ = std::chrono::steady_clock::now();
}

LoggedComponent component_from(const firtp_lcm::config_t& config) {
    const std::vector<std::string> args = split_words(config.args);
    ComponentOptions options;
    if (config.command == "serve") options = parse_serve_options(args);
    else if (config.command == "run") options = parse_run_options(args);
    else throw std::runtime_error(cat("FIRTP_CONFIG from an unknown command '", config.command, "'"));

    LoggedComponent c;
    std::optional<LoggedIni> ini;
    if (!config.ini_file.empty()) {
        ini.emplace(config.ini_file, config.ini_text);
        options.plan.ini = ini->path();
    } else {
        options.plan.ini.reset();
    }
    try {
        c.machine = load_machine_config(options.plan);
    } catch (const std::exception& e) {
        throw std::runtime_error(cat("the logged machine (", config.ini_file.empty() ? "built-in" : config.ini_file,
                                     ") does not load: ", e.what()));
    }
    c.settings.queue = config.queue;
    c.settings.max_blocks = config.max_blocks;
    c.settings.stream_depth = config.stream_depth;
    c.settings.plan_budget_us = config.plan_budget_us;
    c.description = cat(config.sender, ": ", config.command, ", ",
                        config.ini_file.empty() ? std::string("built-in machine") : config.ini_file);
    if (!args.empty()) {
        c.description += ", args";
        for (const std::string& word : args) c.description.append(" ").append(word);
    }
    return c;
}

}  // namespace firtp::cli
