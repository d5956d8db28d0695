// The manifest (formatManifest / parseManifest / readManifest) and planBatch, which writes a whole plan.
#include "hs/batch/Manifest.h"

#include "hs/generate/Seeds.h"
#include "hs/io/AtomicFile.h"
#include "hs/scene/JsonText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <map>

namespace hs::batch {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxJobNameLength = 64;
/// Lines before the first job: the magic line and the column line.
constexpr std::size_t kHeaderLines = 2;

bool isJobName(std::string_view name) {
    if (name.empty() || name.size() > kMaxJobNameLength)
        return false;
    for (std::size_t i = 0; i < name.size(); ++i) {
        const char c = name[i];
        const bool alnum = std::isalnum(static_cast<unsigned char>(c)) != 0;
        if (!alnum && (i == 0 || (c != '-' && c != '_')))
            return false;
    }
    return true;
}

/// What is wrong with a manifest path that must lie in `folder`, or "" when it is fine.
std::string pathProblem(std::string_view path, std::string_view folder) {
    const std::string escapes = " escapes the batch folder";
    if (path.empty())
        return "is empty";
    if (path.front() == '/')
        return "is absolute: it" + escapes;
    if (path.find('\\') != std::string_view::npos)
        return "holds a backslash (paths are '/'-separated)";
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t slash = path.find('/', start);
        parts.push_back(path.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
        if (slash == std::string_view::npos)
            break;
        start = slash + 1;
    }
    for (std::string_view part : parts) {
        if (part == "..")
            return "climbs with \"..\": it" + escapes;
        if (part.empty() || part == ".")
            return "holds an empty or \".\" component";
        for (const char c : part)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-')
                return "holds the character " + scene::quoteText(std::string(1, c)) + " (allowed A-Z a-z 0-9 . _ -)";
    }
    if (parts.size() < 2 || parts.front() != folder)
        return "lies outside " + std::string(folder) + "/";
    return {};
}

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        std::string_view line =
            text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back(line);
        if (end == std::string_view::npos)
            break;
        start = end + 1;
    }
    return lines;
}

std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (std::size_t start = 0;;) {
        const std::size_t tab = line.find('\t', start);
        fields.push_back(line.substr(start, tab == std::string_view::npos ? std::string_view::npos : tab - start));
        if (tab == std::string_view::npos)
            return fields;
        start = tab + 1;
    }
}

template <class T>
bool parseUnsigned(std::string_view text, T& out) {
    if (text.empty() || text.front() == '+' || text.front() == '-')
        return false;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size();
}

/// Two outputs that are the same folder, or one inside the other, on a file system that folds case or not.
Status checkCollisions(const std::vector<Job>& jobs, const std::string& sourceName) {
    std::vector<std::pair<std::string, std::size_t>> outputs;
    for (const Job& job : jobs)
        outputs.emplace_back(lowerCase(job.output), job.index);
    std::sort(outputs.begin(), outputs.end());
    for (std::size_t i = 1; i < outputs.size(); ++i) {
        const auto& [a, ia] = outputs[i - 1];
        const auto& [b, ib] = outputs[i];
        const bool same = a == b;
        const bool nested = b.size() > a.size() && b.compare(0, a.size(), a) == 0 && b[a.size()] == '/';
        if (same || nested) {
            const std::size_t first = std::min(ia, ib);
            const std::size_t second = std::max(ia, ib);
            return fail(ErrorCode::InvalidInput,
                        sourceName + ": line " + std::to_string(second + kHeaderLines + 1) + ": output " +
                            scene::quoteText(jobs[second].output) + (same ? " collides with" : " nests with") +
                            " the output " + scene::quoteText(jobs[first].output) + " of line " +
                            std::to_string(first + kHeaderLines + 1) + " (every job needs its own folder)");
        }
    }
    return {};
}

Result<Job> parseJobLine(std::string_view line, std::size_t expectedIndex, const std::string& where) {
    const auto fields = splitFields(line);
    if (fields.size() != 5)
        return fail(ErrorCode::InvalidInput, where + ": " + std::to_string(fields.size()) +
                                                 " tab-separated fields (expected 5: " + std::string(kManifestColumns) +
                                                 ")");
    Job job;
    if (!parseUnsigned(fields[0], job.index) || job.index != expectedIndex)
        return fail(ErrorCode::InvalidInput, where + ": index " + scene::quoteText(fields[0]) + " (expected " +
                                                 std::to_string(expectedIndex) +
                                                 ": jobs are numbered from 0 in order)");
    job.name = std::string(fields[1]);
    if (!isJobName(job.name))
        return fail(ErrorCode::InvalidInput, where + ": job " + scene::quoteText(job.name) +
                                                 " is not a valid name (1-64 characters: letters, digits, '-' and "
                                                 "'_', starting with a letter or digit)");
    job.caseFile = std::string(fields[2]);
    if (const std::string problem = pathProblem(job.caseFile, kCasesFolder); !problem.empty())
        return fail(ErrorCode::InvalidInput, where + ": case " + scene::quoteText(job.caseFile) + " " + problem);
    if (!parseUnsigned(fields[3], job.seed))
        return fail(ErrorCode::InvalidInput, where + ": seed " + scene::quoteText(fields[3]) +
                                                 " is not an unsigned 64-bit integer (0..18446744073709551615)");
    job.output = std::string(fields[4]);
    if (const std::string problem = pathProblem(job.output, kPackagesFolder); !problem.empty())
        return fail(ErrorCode::InvalidInput, where + ": output " + scene::quoteText(job.output) + " " + problem);
    return job;
}

std::string caseName(const CaseTemplate& t, std::size_t caseIndex) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "-%04zu", caseIndex);
    return t.name + suffix;
}

std::string jobName(const std::string& caseName, std::size_t variant) {
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, "-v%02zu", variant);
    return caseName + suffix;
}

Status createFolders(const std::string& batchFolder) {
    for (std::string_view sub : {kCasesFolder, kPackagesFolder, kStatusFolder, kLogsFolder}) {
        std::error_code ec;
        fs::create_directories(batchPath(batchFolder, sub), ec);
        if (ec)
            return fail(ErrorCode::IoError, batchPath(batchFolder, sub) + ": " + ec.message());
    }
    return {};
}

} // namespace

std::string batchPath(const std::string& batchFolder, std::string_view relative) {
    return (fs::path(batchFolder) / fs::path(std::string(relative))).string();
}

std::string formatManifest(const Manifest& manifest) {
    std::string text = std::string(kManifestMagic) + "\n" + std::string(kManifestColumns) + "\n";
    for (const Job& job : manifest.jobs)
        text += std::to_string(job.index) + "\t" + job.name + "\t" + job.caseFile + "\t" + std::to_string(job.seed) +
                "\t" + job.output + "\n";
    return text;
}

Result<Manifest> parseManifest(std::string_view text, const std::string& sourceName) {
    const auto lines = splitLines(text);
    if (lines.empty() || lines[0] != kManifestMagic)
        return fail(ErrorCode::InvalidInput,
                    sourceName + ": line 1: expected " + scene::quoteText(kManifestMagic) + " (not a batch manifest)");
    if (lines.size() < 2 || lines[1] != kManifestColumns)
        return fail(ErrorCode::InvalidInput,
                    sourceName + ": line 2: expected the column names " + scene::quoteText(kManifestColumns));
    Manifest manifest;
    std::map<std::string, std::size_t> lineOfName;
    for (std::size_t i = kHeaderLines; i < lines.size(); ++i) {
        if (lines[i].empty() && i + 1 == lines.size())
            break;
        if (manifest.jobs.size() >= kMaxJobs)
            return fail(ErrorCode::LimitExceeded,
                        sourceName + ": more than " + std::to_string(kMaxJobs) + " jobs (the limit of a plan)");
        const std::string where = sourceName + ": line " + std::to_string(i + 1);
        auto job = parseJobLine(lines[i], manifest.jobs.size(), where);
        if (!job)
            return job.failure();
        const auto [it, inserted] = lineOfName.emplace(job->name, i + 1);
        if (!inserted)
            return fail(ErrorCode::InvalidInput, where + ": job " + scene::quoteText(job->name) +
                                                     " repeats the job of line " + std::to_string(it->second));
        manifest.jobs.push_back(std::move(*job));
    }
    HS_TRY(checkCollisions(manifest.jobs, sourceName));
    return manifest;
}

Result<Manifest> readManifest(const std::string& batchFolder) {
    const std::string path = batchPath(batchFolder, kManifestFile);
    std::error_code ec;
    if (!fs::exists(path, ec))
        return fail(ErrorCode::NotFound,
                    path + ": no manifest: plan the batch first (hysteroscene-cli batch plan CURRICULUM.json -o " +
                        batchFolder + ")");
    auto text = io::readFile(path, kMaxManifestBytes);
    if (!text)
        return text.failure();
    return parseManifest(*text, path);
}

Result<PlanResult> planBatch(const LoadedCurriculum& loaded, const std::string& curriculumText,
                             const std::string& batchFolder) {
    const Curriculum& c = loaded.curriculum;
    PlanResult result;
    std::vector<std::pair<std::string, scene::CaseSpec>> cases;
    for (std::size_t t = 0; t < c.templates.size(); ++t) {
        for (std::size_t k = 0; k < static_cast<std::size_t>(c.templates[t].cases); ++k) {
            const std::string name = caseName(c.templates[t], k);
            const std::string caseFile = std::string(kCasesFolder) + "/" + name + ".json";
            scene::CaseSpec spec = sampleCase(loaded, t, k);
            for (std::size_t v = 0; v < static_cast<std::size_t>(c.variants); ++v) {
                Job job;
                job.index = result.manifest.jobs.size();
                job.name = jobName(name, v);
                job.caseFile = caseFile;
                job.seed = c.variants == 1 ? spec.seed : generate::variantSeed(spec.seed, v);
                job.output = std::string(kPackagesFolder) + "/" + job.name;
                result.manifest.jobs.push_back(std::move(job));
            }
            cases.emplace_back(caseFile, std::move(spec));
        }
    }
    result.cases = cases.size();
    const std::string manifestText = formatManifest(result.manifest);
    const std::string manifestPath = batchPath(batchFolder, kManifestFile);

    std::error_code ec;
    if (fs::exists(manifestPath, ec)) {
        auto existing = io::readFile(manifestPath, kMaxManifestBytes);
        if (!existing)
            return existing.failure();
        if (*existing != manifestText)
            return fail(ErrorCode::InvalidInput,
                        batchFolder + ": holds another plan (its manifest.tsv differs from this curriculum's); plan "
                                      "into a new folder, or delete the old one");
        result.unchanged = true;
    }
    HS_TRY(createFolders(batchFolder));
    for (const auto& [file, spec] : cases)
        HS_TRY(scene::saveCase(spec, batchPath(batchFolder, file)));
    HS_TRY(io::writeFileAtomically(batchPath(batchFolder, kCurriculumFile), curriculumText));
    HS_TRY(io::writeFileAtomically(manifestPath, manifestText));
    return result;
}

} // namespace hs::batch
