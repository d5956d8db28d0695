// The shape model against the published morphometry: for each patient group of tests/data/anatomy/morphometry.csv,
// the sampled dimension's mean lies within the published mean +- 1 SD, and where a 95 % range is published at least
// 95 % of the samples lie inside it.
#include "hs/anatomy/Cohort.h"
#include "hs/anatomy/ShapeModel.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

using namespace hs::anatomy;
using hs::clinical::PatientParams;

namespace {

constexpr int kSamplesPerGroup = 40;

struct Row {
    std::map<std::string, std::string> field;
    double number(const std::string& key) const { return std::stod(field.at(key)); }
    bool has(const std::string& key) const { return !field.at(key).empty(); }
};

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (const char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            out.emplace_back();
        else
            out.back() += c;
    }
    return out;
}

std::vector<Row> readTable() {
    std::ifstream in(hs::test::testDataDir() / "anatomy" / "morphometry.csv");
    EXPECT_TRUE(in.good()) << "tests/data/anatomy/morphometry.csv not found";
    std::string line;
    std::getline(in, line);
    const auto header = splitCsv(line);
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        const auto cells = splitCsv(line);
        EXPECT_EQ(cells.size(), header.size()) << line;
        Row row;
        for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row.field[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

double dimension(const UterusDimensions& d, const std::string& name) {
    static const std::map<std::string, double UterusDimensions::*> fields = {
        {"lengthMm", &UterusDimensions::lengthMm},
        {"corpusLengthMm", &UterusDimensions::corpusLengthMm},
        {"cervixLengthMm", &UterusDimensions::cervixLengthMm},
        {"widthMm", &UterusDimensions::widthMm},
        {"apDepthMm", &UterusDimensions::apDepthMm},
        {"cavityLengthMm", &UterusDimensions::cavityLengthMm},
        {"cavityWidthMm", &UterusDimensions::cavityWidthMm},
        {"cavityAreaCm2", &UterusDimensions::cavityAreaCm2},
        {"internalOsWidthMm", &UterusDimensions::internalOsWidthMm},
        {"cervixDiameterMm", &UterusDimensions::cervixDiameterMm},
        {"fundalWallMm", &UterusDimensions::fundalWallMm},
    };
    const auto it = fields.find(name);
    EXPECT_NE(it, fields.end()) << "unknown dimension " << name;
    return it == fields.end() ? 0.0 : d.*(it->second);
}

bool inGroup(const PatientParams& p, const Row& row) {
    const std::string meno = row.field.at("menopausal");
    return p.ageYears >= row.number("age_min") && p.ageYears < row.number("age_max") + 1.0 &&
           p.parity >= row.number("parity_min") && p.parity <= row.number("parity_max") &&
           p.gravidity >= row.number("gravidity_min") && p.gravidity <= row.number("gravidity_max") &&
           (meno == "any" || (meno == "yes") == p.menopausal);
}

} // namespace

TEST(Morphometry, TableListsItsSourcesAndChecksMostRows) {
    const auto rows = readTable();
    int checked = 0;
    for (const auto& r : rows) {
        EXPECT_FALSE(r.field.at("source").empty()) << r.field.at("id");
        checked += r.field.at("checked") == "yes" ? 1 : 0;
    }
    EXPECT_GE(checked, 20);
}

TEST(Morphometry, SampledGroupsMatchThePublishedMeansAndRanges) {
    auto model = loadShapeModel(HS_ANATOMY_DEFAULT_MODEL);
    ASSERT_TRUE(model.ok()) << model.error().message();
    const auto& layout = *model->layout();
    hs::Rng rng(1234);
    std::uint64_t seed = 0;
    for (const auto& row : readTable()) {
        if (row.field.at("checked") != "yes")
            continue;
        const std::string id = row.field.at("id"), name = row.field.at("dimension");
        std::vector<double> values;
        while (static_cast<int>(values.size()) < kSamplesPerGroup) {
            const PatientParams p = samplePatient(rng);
            if (!inGroup(p, row))
                continue;
            const auto organ = model->sample(p, ++seed);
            ASSERT_TRUE(organ.ok());
            values.push_back(dimension(*measureUterus(*organ, layout), name));
        }
        double mean = 0.0;
        for (const double v : values)
            mean += v / static_cast<double>(values.size());
        const double target = row.number("mean"), sd = row.number("sd");
        EXPECT_NEAR(mean, target, sd) << id << ": sampled mean " << mean << " vs published " << target << " +- " << sd;
        if (row.has("lo95")) {
            const double lo = row.number("lo95"), hi = row.number("hi95");
            const auto inside =
                std::count_if(values.begin(), values.end(), [&](double v) { return v >= lo && v <= hi; });
            EXPECT_GE(static_cast<double>(inside) / static_cast<double>(values.size()), 0.95)
                << id << ": " << inside << " of " << values.size() << " inside [" << lo << ", " << hi << "]";
        }
        std::printf("%-34s %-18s sampled %7.2f  published %7.2f +- %.2f\n", id.c_str(), name.c_str(), mean, target, sd);
    }
}

TEST(Morphometry, ExpectedDimensionsHoldNinetyFivePercentOfSampledShapes) {
    // The 95 % range the workstation shows beside a patient's organ: sampled shapes of that patient fall in it.
    PatientParams patient; // the default 35-year-old primipara
    const ExpectedDimensions e = expectedDimensions(patient);
    EXPECT_DOUBLE_EQ(e.cavityLengthMm.mean, expectedShape(patient).cavityLengthMm);
    hs::Rng rng(7);
    int inside = 0, total = 0;
    for (int i = 0; i < 2000; ++i) {
        const UterusShapeParams s = sampleShape(patient, 51.0, rng);
        for (const auto& [value, range] :
             {std::pair{s.lengthMm, e.lengthMm}, std::pair{s.widthMm, e.widthMm}, std::pair{s.apDepthMm, e.apDepthMm},
              std::pair{s.cavityLengthMm, e.cavityLengthMm}, std::pair{s.cavityWidthMm, e.cavityWidthMm},
              std::pair{s.cervixLengthMm, e.cervixLengthMm}}) {
            inside += value >= range.low() && value <= range.high();
            ++total;
        }
    }
    const double share = double(inside) / total;
    EXPECT_GT(share, 0.93);
    EXPECT_LT(share, 0.97);

    // A postmenopausal patient's ranges are smaller.
    PatientParams old = patient;
    old.ageYears = 75.0;
    old.menopausal = true;
    old.cyclePhase.reset();
    EXPECT_LT(expectedDimensions(old).lengthMm.high(), e.lengthMm.mean);
}
