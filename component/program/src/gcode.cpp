#include <firtp/gcode.hpp>

#include "canon_recorder.hpp"
#include "interpreter_files.hpp"
#include "python_comment.hpp"
#include "rs274_canon.hpp"

#include <firtp/text_cat.hpp>

#include <interp_base.hh>
#include <interp_return.hh>

#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>

// Sanitized builds (docs/HARDENING.md): LinuxCNC's interpreter and the Python it embeds keep
// allocations for the life of the process, which LeakSanitizer would report at exit.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FIRTP_LSAN_HOOK 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(FIRTP_LSAN_HOOK)
extern "C" const char* __lsan_default_suppressions() {
    return "leak:librs274.so\nleak:libpython3\nleak:libpyplugin.so\nleak:libboost_python\n";
}
// ... quietly: the table of suppressions used would land on every firtp's stderr (tests read it).
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

namespace firtp {

GcodeError::GcodeError(std::string file, int line, int column, const std::string& message)
    : std::runtime_error(column > 0 ? cat(file, ":", std::to_string(line), ":", std::to_string(column), ": ", message)
                                    : cat(file, ":", std::to_string(line), ": ", message)),
      file_(std::move(file)), line_(line), column_(column) {}

namespace {

using gcode::CanonRecorder;
using gcode::Place;

// LinuxCNC's interpreter: one per process, as in LinuxCNC's own programs.
InterpBase& interpreter() {
    static InterpBase* interp = makeInterp();
    return *interp;
}

std::string text_of(char* (InterpBase::*get)(char*, std::size_t), InterpBase& interp) {
    char buffer[1024] = "";
    (interp.*get)(buffer, sizeof buffer);
    return buffer;
}

// INI_FILE_NAME, which the interpreter reads, for the length of one program.
class IniEnvironment {
public:
    explicit IniEnvironment(const std::filesystem::path& ini) {
        if (const char* old = std::getenv("INI_FILE_NAME")) old_ = old;
        if (ini.empty()) ::unsetenv("INI_FILE_NAME");
        else ::setenv("INI_FILE_NAME", ini.c_str(), 1);
    }
    ~IniEnvironment() {
        if (old_) ::setenv("INI_FILE_NAME", old_->c_str(), 1);
        else ::unsetenv("INI_FILE_NAME");
    }
    IniEnvironment(const IniEnvironment&) = delete;
    IniEnvironment& operator=(const IniEnvironment&) = delete;

private:
    std::optional<std::string> old_;
};

class Run {
public:
    Run(InterpBase& interp, const std::filesystem::path& path, std::string shown_as)
        : interp_(interp), path_(path.string()), shown_as_(std::move(shown_as)) {}

    // The interpreter's place, with the file as the user named it.
    Place where() {
        std::string file = text_of(&InterpBase::file_name, interp_);
        if (file.empty() || file == path_) file = shown_as_;
        return {file, interp_.sequence_number()};
    }

    // LinuxCNC's words for an error status.
    std::string message(int status) {
        char text[1024] = "";
        interp_.error_text(status, text, sizeof text);
        return text[0] != '\0' ? text : cat("interpreter status ", std::to_string(status));
    }

    GcodeError error(int status) {
        const Place at = where();
        return GcodeError(at.file, at.line, 0, message(status));
    }

private:
    InterpBase& interp_;
    std::string path_;
    std::string shown_as_;
};

// Keeps a whole program in memory.
class Collect : public ProgramSink {
public:
    explicit Collect(Program& program) : program_(program) {}
    void block(const Block& block) override { program_.blocks.push_back(block); }
    void event(const ProgramEvent& event) override { program_.events.push_back(event); }
    void joined(const JoinedMoves& joined) override { program_.joined = joined; }

private:
    Program& program_;
};

// Reads `path` through the interpreter into `sink`; errors name `shown_as`.
void interpret(const std::filesystem::path& path, const std::string& shown_as, const MachineConfig& machine,
               const AxisVector& start, ProgramSink& sink) {
    static std::mutex one_at_a_time;
    const std::lock_guard lock(one_at_a_time);
    gcode::InterpreterFiles files(machine);  // parameter file and tool table, removed at the end
    const IniEnvironment ini(machine.ini_file);
    InterpBase& interp = interpreter();
    Run run(interp, path, shown_as);

    CanonRecorder recorder(machine, start, sink, [&run] { return run.where(); });
    gcode::set_canon_recorder(&recorder);
    gcode::set_canon_parameter_file(files.parameter_file());
    gcode::set_canon_axes(machine.limits.axes);
    struct Detach {
        InterpBase& interp;
        ~Detach() {
            interp.close();
            gcode::set_canon_recorder(nullptr);
        }
    } detach{interp};

    std::optional<GcodeError> error;
    if (const int status = interp.init(); status > INTERP_MIN_ERROR)
        error = GcodeError(shown_as, 0, 0, cat("LinuxCNC's interpreter did not start: ", run.message(status)));
    else if (const int code = machine.startup_code.empty() ? INTERP_OK : interp.execute(machine.startup_code.c_str());
             code > INTERP_MIN_ERROR && code != INTERP_EXECUTE_FINISH)
        error = GcodeError(machine.ini_file.string(), 0, 0,
                           cat("[RS274NGC]RS274NGC_STARTUP_CODE '", machine.startup_code, "': ", run.message(code)));
    else if (const int open = interp.open(path.c_str()); open > INTERP_MIN_ERROR)
        error = GcodeError(shown_as, 0, 0, "cannot open file");
    // A loop that never moves (an O-word while with no motion) would run forever, as in LinuxCNC:
    // refused once more lines than a program may have blocks ran without a block or an event.
    std::size_t idle_lines = 0, seen = 0;
    while (!error && !recorder.failed()) {
        if (const std::size_t made = recorder.blocks() + recorder.events(); made != seen) seen = made, idle_lines = 0;
        if (++idle_lines > std::max<std::size_t>(machine.max_program_blocks, 1000)) {
            const Place at = run.where();
            error = GcodeError(at.file, at.line, 0,
                               cat("more than ", std::to_string(std::max<std::size_t>(machine.max_program_blocks, 1000)),
                                   " lines ran without a move: an endless loop?"));
            break;
        }
        const int read = interp.read();
        if (read == INTERP_ENDFILE) break;
        if (read > INTERP_MIN_ERROR) {
            error = run.error(read);
            break;
        }
        if (const auto problem = gcode::python_comment_problem(text_of(&InterpBase::line_text, interp))) {
            const Place at = run.where();
            error = GcodeError(at.file, at.line, problem->column, problem->what);
            break;
        }
        const int status = interp.execute();
        if (status == INTERP_EXIT) break;
        if (status > INTERP_MIN_ERROR && status != INTERP_EXECUTE_FINISH) error = run.error(status);
    }
    if (!error && recorder.failed()) error = recorder.failed();
    if (error) {
        interp.reset();
        throw *error;
    }
    interp.exit();  // writes the parameters to the temporary copy
    recorder.finish();
}

Program collect(const std::filesystem::path& path, const std::string& shown_as, const MachineConfig& machine,
                const AxisVector& start) {
    Program program;
    program.file = shown_as;
    program.start = start;
    Collect sink(program);
    interpret(path, shown_as, machine, start, sink);
    return program;
}

// A path the interpreter can open, named as the user named it in errors.
std::filesystem::path openable(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::ifstream(path) || std::filesystem::is_directory(path, ec))
        throw GcodeError(path.string(), 0, 0, "cannot open file");
    return std::filesystem::absolute(path, ec);
}

}  // namespace

Program parse_gcode(std::string_view text, const std::string& file_name, const MachineConfig& machine,
                    const AxisVector& start) {
    gcode::TemporaryDirectory dir;
    const std::filesystem::path path = dir.path() / "program.ngc";
    std::ofstream(path, std::ios::binary) << text;
    return collect(path, file_name, machine, start);
}

Program read_gcode(const std::filesystem::path& path, const MachineConfig& machine, const AxisVector& start) {
    return collect(openable(path), path.string(), machine, start);
}

void read_gcode(const std::filesystem::path& path, const MachineConfig& machine, const AxisVector& start,
                ProgramSink& sink) {
    interpret(openable(path), path.string(), machine, start, sink);
}

}  // namespace firtp
