// sbatch array scripts for a batch, their submission, and sacct's view of them.
#include "hs/batch/Slurm.h"

#include "hs/batch/Job.h"
#include "hs/io/AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <optional>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace hs::batch {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSubmittedFile = "submitted.tsv";

struct ProgramOutput {
    int exitCode = -1;
    std::string out; ///< stdout
};

/// Runs a program found on PATH with `args`, stdin from /dev/null, stderr to ours (or to /dev/null when `quiet`);
/// NotFound when it is not there.
Result<ProgramOutput> runProgram(std::vector<std::string> args, bool quiet = false) {
    int pipeFds[2];
    if (pipe(pipeFds) != 0)
        return fail(ErrorCode::IoError, "cannot create a pipe: " + std::string(std::strerror(errno)));
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeFds[0]);
    if (quiet)
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int error = posix_spawnp(&pid, args[0].c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipeFds[1]);
    if (error != 0) {
        close(pipeFds[0]);
        return fail(error == ENOENT ? ErrorCode::NotFound : ErrorCode::IoError,
                    args[0] + ": cannot run it: " + std::strerror(error));
    }
    ProgramOutput output;
    char buffer[4096];
    ssize_t n = 0;
    while ((n = read(pipeFds[0], buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR))
        if (n > 0)
            output.out.append(buffer, static_cast<std::size_t>(n));
    close(pipeFds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    output.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return output;
}

bool allOf(std::string_view text, const char* allowed) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [allowed](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || std::strchr(allowed, c) != nullptr;
    });
}

/// Digits only, at most 9 of them (no overflow), as a number.
std::optional<long> wholeNumber(std::string_view text) {
    if (text.empty() || text.size() > 9 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
        return std::nullopt;
    return std::stol(std::string(text));
}

/// Splits at every `separator`.
std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos)
            return parts;
        start = end + 1;
    }
}

/// '…' for the shell.
std::string shellQuote(const std::string& text) {
    std::string q = "'";
    for (char c : text)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// "0-3,7,9-12" for sorted indices.
std::string rangeList(const std::vector<std::size_t>& indices) {
    std::string spec;
    for (std::size_t i = 0; i < indices.size();) {
        std::size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1)
            ++j;
        spec += (spec.empty() ? "" : ",") + std::to_string(indices[i]);
        if (j > i)
            spec += "-" + std::to_string(indices[j]);
        i = j + 1;
    }
    return spec;
}

std::string scriptText(const std::string& batchFolder, const SlurmParams& p, std::size_t chunk, std::size_t offset,
                       const std::string& arraySpec) {
    const std::string folder = fs::absolute(batchFolder).lexically_normal().string();
    std::string t = "#!/bin/bash\n";
    t += "# Array tasks of the batch " + folder + ", chunk " + std::to_string(chunk) +
         ": task index = " + std::to_string(offset) +
         " + SLURM_ARRAY_TASK_ID. Written by hysteroscene-cli batch "
         "slurm; resubmitting runs only what is missing or failed.\n";
    t += "#SBATCH --job-name=hysteroscene-" + std::to_string(chunk) + "\n";
    t += "#SBATCH --array=" + arraySpec + "\n";
    if (!p.partition.empty())
        t += "#SBATCH --partition=" + p.partition + "\n";
    t += "#SBATCH --time=" + p.time + "\n";
    t += "#SBATCH --mem=" + p.memory + "\n";
    t += "#SBATCH --cpus-per-task=" + std::to_string(p.threads) + "\n";
    t += "#SBATCH --ntasks=1\n";
    t += "#SBATCH --output=" + (fs::path(folder) / std::string(kLogsFolder) / "slurm-%A_%a.out").string() + "\n";
    t += "set -u\n";
    t += "exec " + shellQuote(p.executable) + " batch run " + shellQuote(folder) + " --task-index $((" +
         std::to_string(offset) + " + SLURM_ARRAY_TASK_ID)) --tasks-per-index " + std::to_string(p.tasksPerIndex) +
         " --threads " + std::to_string(p.threads) + "\n";
    return t;
}

} // namespace

std::optional<double> slurmTimeSeconds(std::string_view time) {
    long days = 0;
    std::string_view clock = time;
    const std::size_t dash = time.find('-');
    if (dash != std::string_view::npos) {
        const auto d = wholeNumber(time.substr(0, dash));
        if (!d)
            return std::nullopt;
        days = *d;
        clock = time.substr(dash + 1);
    }
    std::vector<long> fields;
    for (std::string_view part : split(clock, ':')) {
        const auto value = wholeNumber(part);
        if (!value)
            return std::nullopt;
        fields.push_back(*value);
    }
    long seconds = 0;
    if (dash == std::string_view::npos) { // minutes, minutes:seconds, hours:minutes:seconds
        if (fields.size() == 1)
            seconds = fields[0] * 60;
        else if (fields.size() == 2)
            seconds = fields[0] * 60 + fields[1];
        else if (fields.size() == 3)
            seconds = (fields[0] * 60 + fields[1]) * 60 + fields[2];
        else
            return std::nullopt;
    } else { // days-hours, days-hours:minutes, days-hours:minutes:seconds
        if (fields.empty() || fields.size() > 3)
            return std::nullopt;
        seconds = fields[0] * 3600 + (fields.size() > 1 ? fields[1] * 60 : 0) + (fields.size() > 2 ? fields[2] : 0);
        seconds += days * 86400;
    }
    return static_cast<double>(seconds);
}

std::optional<double> slurmMemoryMib(std::string_view memory) {
    std::string_view digits = memory;
    double unitMib = 1.0; // Slurm's default unit is the megabyte (MiB)
    const char unit = memory.empty() ? '\0' : memory.back();
    if (unit != '\0' && std::strchr("KMGT", unit) != nullptr) {
        unitMib = unit == 'K' ? 1.0 / 1024.0 : unit == 'M' ? 1.0 : unit == 'G' ? 1024.0 : 1024.0 * 1024.0;
        digits = memory.substr(0, memory.size() - 1);
    }
    const auto value = wholeNumber(digits);
    if (!value)
        return std::nullopt;
    return static_cast<double>(*value) * unitMib;
}

Status checkSlurmParams(const SlurmParams& p) {
    if (!p.partition.empty() && !allOf(p.partition, "_-.,"))
        return fail(ErrorCode::InvalidInput,
                    "--partition " + p.partition + ": not a partition name (letters, digits, '_', '-', '.', ',')");
    if (!slurmTimeSeconds(p.time))
        return fail(ErrorCode::InvalidInput,
                    "--time " + p.time + ": not a Slurm time (minutes, MM:SS, HH:MM:SS, D-HH or D-HH:MM:SS)");
    if (!slurmMemoryMib(p.memory))
        return fail(ErrorCode::InvalidInput,
                    "--mem " + p.memory + ": not a Slurm memory size (a whole number, optionally K, M, G or T)");
    if (p.arrayChunk < 1 || p.tasksPerIndex < 1 || p.threads < 1)
        return fail(ErrorCode::InvalidInput, "--array-chunk, --tasks-per-index and --threads must be at least 1");
    if (p.executable.empty() || !fs::path(p.executable).is_absolute())
        return fail(ErrorCode::InvalidInput, "the executable must be an absolute path, got \"" + p.executable + "\"");
    return {};
}

Result<std::vector<SlurmScript>> planSlurmScripts(const std::string& batchFolder, const Manifest& manifest,
                                                  const SlurmParams& params) {
    HS_TRY(checkSlurmParams(params));
    const std::size_t k = params.tasksPerIndex;
    std::vector<std::size_t> pendingTasks;
    for (const Job& job : manifest.jobs) {
        const std::size_t task = job.index / k;
        if ((pendingTasks.empty() || pendingTasks.back() != task) && !jobIsDone(batchFolder, job))
            pendingTasks.push_back(task);
    }
    std::map<std::size_t, std::vector<std::size_t>> byChunk; // chunk -> array indices
    for (std::size_t task : pendingTasks)
        byChunk[task / params.arrayChunk].push_back(task % params.arrayChunk);
    std::vector<SlurmScript> scripts;
    for (const auto& [chunk, indices] : byChunk) {
        SlurmScript s;
        char name[32];
        std::snprintf(name, sizeof name, "array-%03zu.sbatch", chunk);
        s.path = batchPath(batchFolder, std::string(kSlurmFolder) + "/" + name);
        s.taskOffset = chunk * params.arrayChunk;
        s.arraySpec = rangeList(indices);
        s.tasks = indices.size();
        s.text = scriptText(batchFolder, params, chunk, s.taskOffset, s.arraySpec);
        scripts.push_back(std::move(s));
    }
    return scripts;
}

Status writeSlurmScripts(const std::vector<SlurmScript>& scripts) {
    for (const SlurmScript& s : scripts) {
        std::error_code ec;
        fs::create_directories(fs::path(s.path).parent_path(), ec);
        if (ec)
            return fail(ErrorCode::IoError, fs::path(s.path).parent_path().string() + ": " + ec.message());
        HS_TRY(io::writeFileAtomically(s.path, s.text));
    }
    return {};
}

std::optional<std::size_t> clusterMaxArraySize() {
    auto config = runProgram({"scontrol", "show", "config"}, true);
    if (!config || config->exitCode != 0)
        return std::nullopt;
    const std::string& text = config->out;
    const auto at = text.find("MaxArraySize");
    if (at == std::string::npos)
        return std::nullopt;
    const auto equals = text.find('=', at);
    if (equals == std::string::npos)
        return std::nullopt;
    try {
        return static_cast<std::size_t>(std::stoull(text.substr(equals + 1)));
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

Result<std::string> submitSlurmScript(const std::string& batchFolder, const SlurmScript& script) {
    auto run = runProgram({"sbatch", "--parsable", script.path});
    if (!run)
        return run.failure();
    std::string id = run->out.substr(0, run->out.find_first_of(";\n"));
    if (run->exitCode != 0 || id.empty() || !allOf(id, "_"))
        return fail(ErrorCode::BackendFailure,
                    "sbatch " + script.path + " failed (exit code " + std::to_string(run->exitCode) + "): " + run->out);
    const std::string record = batchPath(batchFolder, std::string(kSlurmFolder) + "/" + std::string(kSubmittedFile));
    auto previous = io::readFile(record, 16 * 1024 * 1024);
    const std::string text = (previous ? *previous : std::string()) + id + "\t" +
                             fs::path(script.path).filename().string() + "\t" + script.arraySpec + "\n";
    HS_TRY(io::writeFileAtomically(record, text));
    return id;
}

std::vector<std::string> submittedSlurmJobs(const std::string& batchFolder) {
    std::vector<std::string> ids;
    auto text =
        io::readFile(batchPath(batchFolder, std::string(kSlurmFolder) + "/" + std::string(kSubmittedFile)), 16 << 20);
    if (!text)
        return ids;
    std::size_t start = 0;
    while (start < text->size()) {
        const std::size_t end = std::min(text->find('\n', start), text->size());
        const std::string id = text->substr(start, text->find('\t', start) - start);
        if (allOf(id, "_") && id.size() < end - start + 1)
            ids.push_back(id);
        start = end + 1;
    }
    return ids;
}

Result<std::vector<std::pair<std::string, std::size_t>>> slurmTaskStates(const std::vector<std::string>& jobIds) {
    std::vector<std::pair<std::string, std::size_t>> counts;
    if (jobIds.empty())
        return counts;
    std::string list;
    for (const std::string& id : jobIds)
        list += (list.empty() ? "" : ",") + id;
    auto run = runProgram(
        {"sacct", "--jobs", list, "--allocations", "--noheader", "--parsable2", "--format", "JobID,State"}, true);
    if (!run)
        return run.failure();
    if (run->exitCode != 0)
        return fail(ErrorCode::BackendFailure, "sacct failed (exit code " + std::to_string(run->exitCode) + ")");
    std::map<std::string, std::size_t> byState;
    std::size_t start = 0;
    const std::string& out = run->out;
    while (start < out.size()) {
        const std::size_t end = std::min(out.find('\n', start), out.size());
        const std::string line = out.substr(start, end - start);
        if (const auto bar = line.find('|'); bar != std::string::npos) {
            const std::string state = line.substr(bar + 1, line.find(' ', bar + 1) - bar - 1);
            if (!state.empty())
                ++byState[state];
        }
        start = end + 1;
    }
    counts.assign(byState.begin(), byState.end());
    return counts;
}

} // namespace hs::batch
