#include "hs/widgets/panels/SceneWarnings.h"

#include <QCoreApplication>
#include <QStringList>

#include <string_view>

namespace hs::widgets {

namespace {

constexpr const char* kContext = "hs::widgets::SceneWarnings";

/// What a warning of each source means, in the order the scene lists them. "mesh-" stands for every mesh bar.
struct Meaning {
    std::string_view source;
    const char* text;
};
constexpr Meaning kMeanings[] = {
    {"texture", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                  "The texture stage substituted or left out part of the look: the surface may not "
                                  "look as the case describes.")},
    {"pathology", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                    "A pathology could not be placed or grown exactly as asked (moved off a tubal "
                                    "ostium or another pathology, or grown to another size or type): look at it in "
                                    "the 3-D view.")},
    {"merge", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                "Joining the pathologies to the organ changed or dropped part of one: check where "
                                "they meet.")},
    {"meshing", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                  "The mesher repaired or approximated part of the body: the mesh may differ from "
                                  "the shape it was made from.")},
    {"descriptors", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                      "A measured FIGO type, Lasmar score or size differs from the one the case asks "
                                      "for: the trainee meets another grade than intended.")},
    {"measurement", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                      "A clinical measurement fell back to an approximation: the reported figures "
                                      "are less certain.")},
    {"seating", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                  "A polyp lies against the wall over more of its surface than its kind allows: it "
                                  "may look buried in the wall rather than standing in the cavity.")},
    {"hydrometra", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                     "The cavity's opening under the distension pressure was estimated from the "
                                     "organ without its pathologies: distension in the simulator is approximate.")},
    {"simulation", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                     "Part of the visible surface is bound away from the simulation mesh: it may "
                                     "drift off the tissue when the tissue moves.")},
    {"mesh-", QT_TRANSLATE_NOOP("hs::widgets::SceneWarnings",
                                "The tetrahedral mesh misses one of its quality bars: the simulation may be less "
                                "accurate or less stable where the bad elements are.")},
};

constexpr const char* kUnknownSource = QT_TRANSLATE_NOOP(
    "hs::widgets::SceneWarnings", "See the scene package's documentation (docs/scene-format.md) for this warning.");

} // namespace

QString warningMeaning(const std::string& warning) {
    const std::string_view text(warning);
    const std::string_view source = text.substr(0, text.find(": "));
    for (const Meaning& m : kMeanings)
        if (source == m.source || (m.source == "mesh-" && source.rfind("mesh-", 0) == 0))
            return QCoreApplication::translate(kContext, m.text);
    return QCoreApplication::translate(kContext, kUnknownSource);
}

QString warningsHtml(const std::vector<std::string>& warnings) {
    if (warnings.empty())
        return {};
    QStringList items;
    for (const std::string& w : warnings)
        items << QStringLiteral("<li>%1<br><span style='color:#555'>%2</span></li>")
                     .arg(QString::fromStdString(w).toHtmlEscaped(), warningMeaning(w).toHtmlEscaped());
    return QStringLiteral("<ul style='margin-left:0; -qt-list-indent:1'>%1</ul>").arg(items.join(QString()));
}

} // namespace hs::widgets
