// bench_pathology [ORGANS=20] [SIZE_MM=20] [--only skeleton|ca|particles|polyps] [--row TEXT] [--verbose] [--check]:
// for every FIGO type 0-7 (and 2-5) and every growth model, grows a posterior myoma in ORGANS seeded organs, merges it
// and prints how often the measured FIGO type and size (within 10 %) match the request and the merged body is valid,
// with the mean grow and merge times. Then the same for 12 mm polyps, sessile and pedunculated (8 mm stalk), fundal and
// posterior: how often the measured attachment matches (a stalk measured for pedunculated ones, none for sessile ones),
// the size (of the head) is within 10 % and the body merges. --verbose prints what was measured in every organ that
// misses. A request the model refuses as unsupported in every organ is printed as such, not as a failure.
// --check exits with 1 when a row misses the bars of the pathology stage: every request grown, its size within 10 %
// and its body valid in every organ, its measured type (or attachment) as requested in at least 95 % of the organs
// (the test suite runs it over 20 organs).
#include "SampleOrgans.h"

#include "hs/merge/Merge.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace hs;
using namespace hs::pathology;

namespace {

struct Row {
    int grown = 0, typeOk = 0, sizeOk = 0, valid = 0, unsupported = 0;
    double growS = 0.0, mergeS = 0.0, stalkMm = 0.0;
};

/// Grows `request` in organ `s` (seed s + 1), merges it and adds the outcome to `row`.
void runOne(const SurfaceMesh& organ, int s, const PathologyRequest& request, Row& row, bool verbose) {
    PathologyParams params;
    params.seed = static_cast<std::uint64_t>(s + 1);
    params.pathologies.push_back(request);
    const auto t0 = std::chrono::steady_clock::now();
    auto grown = growPathologies(organ, params);
    const auto t1 = std::chrono::steady_clock::now();
    row.growS += std::chrono::duration<double>(t1 - t0).count();
    if (!grown.ok()) {
        row.unsupported += grown.error().code == ErrorCode::Unsupported ? 1 : 0;
        if (verbose)
            std::printf("    organ %2d: refused: %s\n", s + 1, grown.error().detail.c_str());
        return;
    }
    ++row.grown;
    const Descriptors& d = grown->pathologies[0].descriptors;
    const bool typeOk = request.kind == clinical::PathologyKind::Myoma
                            ? d.figo == request.figo
                            : d.pedunculated == (request.attachment == clinical::PolypAttachment::Pedunculated);
    const bool sizeOk = std::fabs(d.sizeMm - request.sizeMm) <= 0.1 * request.sizeMm;
    row.typeOk += typeOk ? 1 : 0;
    row.sizeOk += sizeOk ? 1 : 0;
    row.stalkMm += d.stalkLengthMm;
    auto body = merge::mergeBody(*grown);
    row.mergeS += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    row.valid += body.ok() ? 1 : 0;
    if (verbose && (!typeOk || !sizeOk || !body.ok()))
        std::printf("    organ %2d: FIGO %-4s wall %.3f cavity %.3f outside %.3f endo %.2f serosa %.2f size %.1f "
                    "stalk %.1f base %.1f%s%s\n",
                    s + 1, d.figo.toString().c_str(), d.intramuralFraction, d.cavityFraction, d.outsideFraction,
                    d.endometriumDistanceMm, d.serosaDistanceMm, d.sizeMm, d.stalkLengthMm, d.baseWidthMm,
                    body.ok() ? "" : "; merge: ", body.ok() ? "" : body.error().detail.c_str());
}

/// Prints the row; false when it misses a bar (see --check).
bool printRow(const char* model, const std::string& what, const Row& row, int organs, bool stalk) {
    if (row.unsupported == organs) {
        std::printf("%-10s %-14s unsupported by the model\n", model, what.c_str());
        std::fflush(stdout);
        return true;
    }
    std::printf("%-10s %-14s %6d %6d %8d %6d", model, what.c_str(), row.grown, row.typeOk, row.sizeOk, row.valid);
    if (stalk)
        std::printf(" %8.1f", row.grown > 0 ? row.stalkMm / row.grown : 0.0);
    else
        std::printf(" %8s", "");
    const bool ok =
        row.grown == organs && row.sizeOk == organs && row.valid == organs && 20 * row.typeOk >= 19 * organs;
    std::printf(" %8.3f %8.3f%s\n", row.growS / organs, row.mergeS / organs, ok ? "" : "  below the bar");
    std::fflush(stdout);
    return ok;
}

} // namespace

int main(int argc, char** argv) {
    int organs = 20;
    double size = 20.0;
    std::string only, row; // --row: only the rows whose request contains this text
    bool verbose = false, check = false, allOk = true;
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--verbose") == 0)
            verbose = true;
        else if (std::strcmp(argv[i], "--check") == 0)
            check = true;
        else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            only = argv[++i];
        else if (std::strcmp(argv[i], "--row") == 0 && i + 1 < argc)
            row = argv[++i];
        else if (positional++ == 0)
            organs = std::atoi(argv[i]);
        else
            size = std::atof(argv[i]);
    }
    std::vector<SurfaceMesh> organMeshes;
    for (int s = 1; s <= organs; ++s)
        organMeshes.push_back(test::testOrgan(static_cast<std::uint64_t>(s)));
    const std::vector<clinical::FigoType> figos = {{0, -1}, {1, -1}, {2, -1}, {3, -1}, {4, -1},
                                                   {5, -1}, {6, -1}, {7, -1}, {2, 5}};
    std::printf("%d organs, %.0f mm myoma, posterior wall; 12 mm polyps (stalk 8 mm)\n", organs, size);
    std::printf("%-10s %-14s %6s %6s %8s %6s %8s %8s %8s\n", "model", "request", "grown", "type=", "size10%", "valid",
                "stalk mm", "grow s", "merge s");
    for (clinical::GrowthModel model : {clinical::GrowthModel::CellularAutomaton, clinical::GrowthModel::Skeleton,
                                        clinical::GrowthModel::Particles}) {
        if (!only.empty() && only != toString(model))
            continue;
        for (const clinical::FigoType& f : figos) {
            if (!row.empty() && ("FIGO " + f.toString()).find(row) == std::string::npos)
                continue;
            Row counts;
            if (verbose)
                std::printf("%s FIGO %s\n", std::string(toString(model)).c_str(), f.toString().c_str());
            for (int s = 0; s < organs; ++s)
                runOne(organMeshes[static_cast<std::size_t>(s)], s, test::myoma("m", model, f, size), counts, verbose);
            allOk = printRow(std::string(toString(model)).c_str(), "FIGO " + f.toString(), counts, organs,
                             f.type == 0 || f.type == 7) &&
                    allOk;
        }
    }
    for (clinical::GrowthModel model : {clinical::GrowthModel::Skeleton, clinical::GrowthModel::Particles}) {
        if (!only.empty() && only != "polyps" && only != toString(model))
            continue;
        for (clinical::UterineLocation where :
             {clinical::UterineLocation::Fundal, clinical::UterineLocation::Posterior})
            for (bool pedunculated : {false, true}) {
                const std::string what = std::string(pedunculated ? "pedunc " : "sessile ") +
                                         (where == clinical::UterineLocation::Fundal ? "fund" : "post");
                if (!row.empty() && what.find(row) == std::string::npos)
                    continue;
                if (verbose)
                    std::printf("%s polyp %s\n", std::string(toString(model)).c_str(), what.c_str());
                Row counts;
                for (int s = 0; s < organs; ++s)
                    runOne(organMeshes[static_cast<std::size_t>(s)], s,
                           test::polyp("p", model, 12.0, pedunculated, pedunculated ? 8.0 : 0.0, where), counts,
                           verbose);
                allOk = printRow(std::string(toString(model)).c_str(), what, counts, organs, true) && allOk;
            }
    }
    return check && !allOk ? 1 : 0;
}
