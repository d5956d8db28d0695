#include "hs/anatomy/TrainingData.h"

#include "hs/io/AtomicFile.h"
#include "hs/io/MeshIO.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace hs::anatomy {
namespace {

constexpr std::int64_t kMaxCsvBytes = 16 * 1024 * 1024;
constexpr std::size_t kMaxRows = 100000;
const char* const kColumns[] = {"file", "ageYears", "parity", "gravidity", "heightCm", "weightKg", "menopausal"};

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) {
        const auto b = cell.find_first_not_of(" \t\r");
        const auto e = cell.find_last_not_of(" \t\r");
        cells.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
    }
    if (!line.empty() && line.back() == ',')
        cells.emplace_back();
    return cells;
}

Failure rowError(const std::string& csv, std::size_t line, const std::string& column, const std::string& what) {
    return fail(ErrorCode::InvalidInput, csv + ": line " + std::to_string(line) + ", column '" + column + "': " + what);
}

Result<double> parseNumber(const std::string& text, const std::string& csv, std::size_t line, const char* column) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        return rowError(csv, line, column, "'" + text + "' is not a finite number");
    return v;
}

Result<int> parseCount(const std::string& text, const std::string& csv, std::size_t line, const char* column) {
    auto v = parseNumber(text, csv, line, column);
    if (!v)
        return v.failure();
    if (*v != std::floor(*v) || std::fabs(*v) > 1e6)
        return rowError(csv, line, column, "'" + text + "' is not a whole number");
    return static_cast<int>(*v);
}

Result<bool> parseYesNo(const std::string& text, const std::string& csv, std::size_t line) {
    if (text == "yes" || text == "true" || text == "1")
        return true;
    if (text == "no" || text == "false" || text == "0")
        return false;
    return rowError(csv, line, "menopausal", "'" + text + "' is not one of yes, no, true, false, 1, 0");
}

Result<clinical::PatientParams> parsePatient(const std::vector<std::string>& cells, const std::string& csv,
                                             std::size_t line) {
    clinical::PatientParams p;
    auto age = parseNumber(cells[1], csv, line, "ageYears");
    if (!age)
        return age.failure();
    auto parity = parseCount(cells[2], csv, line, "parity");
    if (!parity)
        return parity.failure();
    auto gravidity = parseCount(cells[3], csv, line, "gravidity");
    if (!gravidity)
        return gravidity.failure();
    auto height = parseNumber(cells[4], csv, line, "heightCm");
    if (!height)
        return height.failure();
    auto weight = parseNumber(cells[5], csv, line, "weightKg");
    if (!weight)
        return weight.failure();
    auto menopausal = parseYesNo(cells[6], csv, line);
    if (!menopausal)
        return menopausal.failure();
    p.ageYears = *age;
    p.parity = *parity;
    p.gravidity = *gravidity;
    p.heightCm = *height;
    p.weightKg = *weight;
    p.menopausal = *menopausal;
    return p;
}

} // namespace

Result<TrainingSet> loadTrainingSet(const std::string& meshDir, const std::string& paramsCsv) {
    auto text = io::readFile(paramsCsv, kMaxCsvBytes);
    if (!text)
        return text.failure();
    std::istringstream in(*text);
    std::string line;
    std::size_t lineNo = 0;
    if (!std::getline(in, line))
        return fail(ErrorCode::InvalidInput, paramsCsv + ": empty; expected a header line");
    ++lineNo;
    const auto header = splitCsvLine(line);
    const std::size_t columns = std::size(kColumns);
    if (header.size() != columns)
        return fail(ErrorCode::InvalidInput, paramsCsv + ": line 1: expected the header "
                                                         "file,ageYears,parity,gravidity,heightCm,weightKg,menopausal");
    for (std::size_t c = 0; c < columns; ++c)
        if (header[c] != kColumns[c])
            return rowError(paramsCsv, 1, header[c], std::string("expected column '") + kColumns[c] + "' here");

    TrainingSet set;
    std::string firstFile;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
        if (set.shapes.size() >= kMaxRows)
            return fail(ErrorCode::LimitExceeded, paramsCsv + ": more than " + std::to_string(kMaxRows) + " rows");
        const auto cells = splitCsvLine(line);
        if (cells.size() != columns)
            return fail(ErrorCode::InvalidInput, paramsCsv + ": line " + std::to_string(lineNo) + ": " +
                                                     std::to_string(cells.size()) + " columns, expected " +
                                                     std::to_string(columns));
        auto patient = parsePatient(cells, paramsCsv, lineNo);
        if (!patient)
            return patient.failure();
        const clinical::PatientParams& p = *patient;
        if (auto valid = validatePatient(p); !valid.ok())
            return fail(ErrorCode::InvalidInput,
                        paramsCsv + ": line " + std::to_string(lineNo) + ": " + valid.error().detail);

        if (cells[0].empty() || std::filesystem::path(cells[0]).is_absolute())
            return rowError(paramsCsv, lineNo, "file", "expected a file name relative to " + meshDir);
        const std::string meshPath = (std::filesystem::path(meshDir) / cells[0]).string();
        auto mesh = io::readSurface(meshPath);
        if (!mesh)
            return mesh.failure();
        if (set.shapes.empty()) {
            set.reference = *mesh;
            firstFile = cells[0];
        } else if (mesh->points.size() != set.reference.points.size() || mesh->triangles != set.reference.triangles) {
            return fail(ErrorCode::InvalidInput, meshPath + ": not in correspondence with the first mesh (" +
                                                     firstFile + "): " + std::to_string(mesh->points.size()) +
                                                     " vertices and " + std::to_string(mesh->triangles.size()) +
                                                     " triangles against " +
                                                     std::to_string(set.reference.points.size()) + " and " +
                                                     std::to_string(set.reference.triangles.size()) +
                                                     " (every mesh needs the same vertices and triangles)");
        }
        set.shapes.push_back(std::move(mesh->points));
        set.patients.push_back(p);
    }
    if (set.shapes.empty())
        return fail(ErrorCode::InvalidInput, paramsCsv + ": no rows after the header");
    return set;
}

} // namespace hs::anatomy
