#include "CliCommon.h"

#include <iostream>

namespace hs::cli {

int reportError(const std::string& command, const Error& error) {
    std::cerr << "hysteroscene-cli: " << command << ": " << error.message() << '\n';
    return exitCodeFor(error);
}

void printJson(std::ostream& out, const nlohmann::ordered_json& value) {
    out << value.dump(2) << '\n';
}

} // namespace hs::cli
