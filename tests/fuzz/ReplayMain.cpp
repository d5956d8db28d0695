// Replays every fuzz harness on its committed corpus and on every regression input, without libFuzzer: the check
// CI runs with the ordinary compiler. A crash, a failed property or a sanitizer report fails the test; the input
// being replayed is printed first.
//
//   test_fuzz_replay                  every harness, tests/fuzz/corpus/<name>/ and tests/data/fuzz-regressions/<name>/
//   test_fuzz_replay NAME [FILE...]   one harness, on the files given (default: its folders)
//   test_fuzz_replay --list           the harness names

#include "FuzzHarnesses.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
// In the sanitized build (the asan preset), malloc returns null for an impossible size, as it does outside
// AddressSanitizer; tools/fuzz.sh gives the shape_model harness the same option. HDF5 sizes its metadata cache
// entries from the file and answers a failed allocation with an error (shape_model/huge-metadata-cache-entry).
// A null then dereferenced still stops the run, and operator new still reports. ASAN_OPTIONS can override this.
extern "C" const char* __asan_default_options() {
    return "allocator_may_return_null=1";
}
#endif

namespace {

namespace fs = std::filesystem;

char g_current[4096] = "";

/// Names the input that crashed (async-signal-safe), then lets the signal do its default.
void onCrash(int signal) {
    const char prefix[] = "\ntest_fuzz_replay: crashed on ";
    (void)!::write(2, prefix, sizeof prefix - 1);
    (void)!::write(2, g_current, std::strlen(g_current));
    (void)!::write(2, "\n", 1);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

std::vector<fs::path> filesIn(const fs::path& folder) {
    std::vector<fs::path> files;
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return files;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file() && entry.path().filename().string().front() != '.')
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

bool replay(const hs::fuzz::Harness& harness, const fs::path& file) {
    std::snprintf(g_current, sizeof g_current, "%s: %s", harness.name, file.c_str());
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "cannot read %s\n", file.c_str());
        return false;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    harness.run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    return true;
}

const hs::fuzz::Harness* find(const std::string& name) {
    for (const auto& h : hs::fuzz::harnesses())
        if (name == h.name)
            return &h;
    return nullptr;
}

} // namespace

int main(int argc, char** argv) {
    for (int s : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL})
        std::signal(s, onCrash);
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "--list") {
        for (const auto& h : hs::fuzz::harnesses())
            std::printf("%s\n", h.name);
        return 0;
    }
    std::vector<const hs::fuzz::Harness*> chosen;
    if (!args.empty()) {
        const auto* h = find(args[0]);
        if (!h) {
            std::fprintf(stderr, "unknown harness '%s' (test_fuzz_replay --list names them)\n", args[0].c_str());
            return 2;
        }
        chosen.push_back(h);
    } else {
        for (const auto& h : hs::fuzz::harnesses())
            chosen.push_back(&h);
    }
    int failures = 0;
    std::printf("%-16s %8s %12s %8s\n", "harness", "corpus", "regressions", "ms");
    for (const auto* h : chosen) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<fs::path> corpus, regressions;
        if (args.size() > 1) {
            corpus.assign(args.begin() + 1, args.end());
        } else {
            corpus = filesIn(fs::path(HS_FUZZ_CORPUS_DIR) / h->name);
            regressions = filesIn(fs::path(HS_FUZZ_REGRESSIONS_DIR) / h->name);
            if (corpus.empty()) {
                std::fprintf(stderr, "%s: no corpus in %s/%s\n", h->name, HS_FUZZ_CORPUS_DIR, h->name);
                ++failures;
            }
        }
        for (const auto& f : corpus)
            failures += replay(*h, f) ? 0 : 1;
        for (const auto& f : regressions)
            failures += replay(*h, f) ? 0 : 1;
        const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
        std::printf("%-16s %8zu %12zu %8lld\n", h->name, corpus.size(), regressions.size(),
                    static_cast<long long>(ms.count()));
    }
    return failures == 0 ? 0 : 1;
}
