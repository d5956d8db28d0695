// bench_pathology [ORGANS=20] [SIZE_MM=20] [MODEL] [-v]: for every FIGO type 0-7 (and 2-5) and every growth model (or
// only MODEL: ca, skeleton, particles), grows a myoma in ORGANS seeded organs, merges it and prints how often the
// measured FIGO type and size (within 10 %) match the request and the merged body is valid, with the mean grow and
// merge times. A type the model refuses as unsupported is printed as such (not as a failure); -v prints on stderr
// every failure's message, the measured type and fractions of every miss, and each run's step times.
#include "SampleOrgans.h"

#include "hs/merge/Merge.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace hs;
using namespace hs::pathology;

int main(int argc, char** argv) {
    std::vector<const char*> args;
    bool verbose = false;
    for (int i = 1; i < argc; ++i)
        (std::strcmp(argv[i], "-v") == 0 ? (void)(verbose = true) : args.push_back(argv[i]));
    const int organs = args.size() > 0 ? std::atoi(args[0]) : 20;
    const double size = args.size() > 1 ? std::atof(args[1]) : 20.0;
    const char* only = args.size() > 2 ? args[2] : nullptr;
    std::vector<SurfaceMesh> organMeshes;
    for (int s = 1; s <= organs; ++s)
        organMeshes.push_back(test::testOrgan(static_cast<std::uint64_t>(s)));
    const std::vector<Figo> figos = {{0, -1}, {1, -1}, {2, -1}, {3, -1}, {4, -1}, {5, -1}, {6, -1}, {7, -1}, {2, 5}};
    std::printf("%d organs, %.0f mm myoma, posterior wall\n", organs, size);
    std::printf("%-10s %-5s %8s %8s %8s %8s %9s %9s\n", "model", "FIGO", "grown", "figo=", "size10%", "valid", "grow s",
                "merge s");
    for (GrowthModel model : {GrowthModel::CellularAutomaton, GrowthModel::Skeleton, GrowthModel::Particles})
        for (const Figo& f : figos) {
            if (only && std::strcmp(only, toString(model)) != 0)
                continue;
            int grownOk = 0, figoOk = 0, sizeOk = 0, valid = 0, unsupported = 0;
            double growS = 0.0, mergeS = 0.0;
            for (int s = 0; s < organs; ++s) {
                PathologyParams params;
                params.seed = static_cast<std::uint64_t>(s + 1);
                params.pathologies.push_back(test::myoma("m", model, f, size));
                const auto t0 = std::chrono::steady_clock::now();
                auto grown = growPathologies(organMeshes[static_cast<std::size_t>(s)], params);
                const auto t1 = std::chrono::steady_clock::now();
                growS += std::chrono::duration<double>(t1 - t0).count();
                if (!grown.ok()) {
                    unsupported += grown.error().code == ErrorCode::Unsupported ? 1 : 0;
                    if (verbose)
                        std::fprintf(stderr, "%s %s organ %d: %s\n", toString(model), f.toString().c_str(), s + 1,
                                     grown.error().detail.c_str());
                    continue;
                }
                ++grownOk;
                if (verbose) {
                    std::fprintf(stderr, "%s %s organ %d: steps", toString(model), f.toString().c_str(), s + 1);
                    for (const StepTiming& st : grown->timings.steps)
                        std::fprintf(stderr, " %s %.3f s", st.name.c_str(), st.seconds);
                    std::fprintf(stderr, ", %zu triangles", grown->pathologies[0].surface.triangles.size());
                    std::fprintf(stderr, "\n");
                }
                const Descriptors& d = grown->pathologies[0].descriptors;
                figoOk += d.figo == f ? 1 : 0;
                sizeOk += std::fabs(d.sizeMm - size) <= 0.1 * size ? 1 : 0;
                auto body = merge::mergeBody(*grown);
                mergeS += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
                valid += body.ok() ? 1 : 0;
                if (verbose && !body.ok())
                    std::fprintf(stderr, "%s %s organ %d: %s\n", toString(model), f.toString().c_str(), s + 1,
                                 body.error().detail.c_str());
                if (verbose && (d.figo != f || std::fabs(d.sizeMm - size) > 0.1 * size))
                    std::fprintf(stderr, "%s %s organ %d: measured FIGO %s, size %.1f mm, cavity %.3f, outside %.3f\n",
                                 toString(model), f.toString().c_str(), s + 1, d.figo.toString().c_str(), d.sizeMm,
                                 d.cavityFraction, d.outsideFraction);
            }
            if (unsupported == organs) {
                std::printf("%-10s %-5s %8s\n", toString(model), f.toString().c_str(), "unsupported by the model");
                std::fflush(stdout);
                continue;
            }
            std::printf("%-10s %-5s %8d %8d %8d %8d %9.3f %9.3f\n", toString(model), f.toString().c_str(), grownOk,
                        figoOk, sizeOk, valid, growS / organs, mergeS / organs);
            std::fflush(stdout);
        }
    return 0;
}
