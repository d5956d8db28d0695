// `convert IN OUT`: any supported mesh format to any other.
#include "CliCommon.h"
#include "Commands.h"
#include "MeshSummary.h"

#include "hs/io/MeshIO.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace hs::cli {
namespace {

struct ConvertOptions {
    std::string input;
    std::string output;
    bool ascii = false;
    CommonOptions common;
};

int runConvert(const ConvertOptions& options) {
    auto outFormat = io::formatFromPath(options.output);
    if (!outFormat.ok())
        return reportError("convert", outFormat.error());
    auto mesh = io::readMesh(options.input);
    if (!mesh.ok())
        return reportError("convert", mesh.error());

    io::WriteOptions writeOptions;
    writeOptions.binary = !options.ascii;
    std::string note;
    Status written;
    if (const auto* tet = std::get_if<TetMesh>(&*mesh)) {
        if (io::isTetFormat(*outFormat)) {
            written = io::writeTetMesh(*tet, options.output, writeOptions);
        } else {
            // A surface format gets the boundary of the tetrahedral mesh, with the region of each face.
            written = io::writeSurface(extractBoundary(*tet), options.output, writeOptions);
            note = "boundary surface of the tetrahedral mesh";
        }
    } else {
        const auto& surface = std::get<SurfaceMesh>(*mesh);
        if (io::isTetFormat(*outFormat) && *outFormat != io::MeshFormat::Vtu)
            return reportError("convert", Error{ErrorCode::Unsupported,
                                                options.input + " is a surface; " + io::formatName(*outFormat) +
                                                    " holds tetrahedra: fill the surface with `hysteroscene-cli "
                                                    "mesh` instead"});
        written = io::writeSurface(surface, options.output, writeOptions);
    }
    if (!written.ok())
        return reportError("convert", written.error());

    const MeshSummary summary = summarize(*mesh);
    if (options.common.json) {
        nlohmann::ordered_json j;
        j["input"] = options.input;
        j["output"] = options.output;
        j["format"] = io::formatName(*outFormat);
        if (!note.empty())
            j["note"] = note;
        toJson(summary, j);
        printJson(std::cout, j);
    } else {
        std::cout << "wrote " << options.output << " (" << io::formatName(*outFormat) << ", " << summary.vertices
                  << " vertices, " << summary.cells << (summary.isTet ? " tetrahedra" : " triangles")
                  << (note.empty() ? "" : ", " + note) << ")\n";
    }
    return kExitOk;
}

} // namespace

void addConvertCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<ConvertOptions>();
    auto* sub = app.add_subcommand("convert", "Convert a mesh between formats (chosen by the file extensions)");
    sub->add_option("IN", options->input, "input mesh")->required();
    sub->add_option("OUT", options->output, "output mesh; written atomically")->required();
    sub->add_flag("--ascii", options->ascii, "write ASCII where the format has both (STL, PLY, VTP, VTU)");
    sub->add_flag("--json", options->common.json, "print JSON for scripts");
    sub->callback([options, &exitCode] { exitCode = runConvert(*options); });
}

} // namespace hs::cli
