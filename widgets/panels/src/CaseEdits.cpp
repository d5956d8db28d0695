#include "hs/widgets/panels/CaseEdits.h"

#include "hs/widgets/document/CaseDocument.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLocale>
#include <QRegularExpression>
#include <QWidget>

namespace hs::widgets {

namespace {

const char* const kContext = "hs::widgets::CaseEdits";

QString tr(const char* text) {
    return QCoreApplication::translate(kContext, text);
}

struct Field {
    const char* path; ///< JSON path with "*" for an array index
    const char* label;
    scene::Range range;
    const char* unit;
};

// The fields a panel edits, with the ranges of the case schema; QT_TRANSLATE_NOOP marks the labels for lupdate.
const Field kFields[] = {
    {"/patient/ageYears", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Age"), scene::limits::kAgeYears,
     QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "years")},
    {"/patient/parity", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Parity"), scene::limits::kParity,
     QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "births")},
    {"/patient/gravidity", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Gravidity"), scene::limits::kGravidity,
     QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "pregnancies")},
    {"/patient/heightCm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Height"), scene::limits::kHeightCm, "cm"},
    {"/patient/weightKg", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Weight"), scene::limits::kWeightKg, "kg"},
    {"/anatomy/dimensions/lengthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Uterine length"),
     scene::limits::kLengthMm, "mm"},
    {"/anatomy/dimensions/widthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Width"), scene::limits::kWidthMm,
     "mm"},
    {"/anatomy/dimensions/apMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "AP depth"), scene::limits::kApMm, "mm"},
    {"/anatomy/dimensions/cavityLengthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Cavity length"),
     scene::limits::kCavityLengthMm, "mm"},
    {"/anatomy/dimensions/cavityWidthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Cavity width"),
     scene::limits::kCavityWidthMm, "mm"},
    {"/anatomy/dimensions/fundalWallThicknessMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Fundal wall thickness"),
     scene::limits::kFundalWallThicknessMm, "mm"},
    {"/anatomy/dimensions/cervixLengthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Cervix length"),
     scene::limits::kCervixLengthMm, "mm"},
    {"/pathologies/*/stalkLengthMm", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Stalk length"),
     scene::limits::kStalkLengthMm, "mm"},
    {"/meshing/targetVertices", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Target vertices"),
     scene::limits::kTargetVertices, ""},
    {"/texture/vesselDensity", QT_TRANSLATE_NOOP("hs::widgets::CaseEdits", "Vessel density"),
     scene::limits::kVesselDensity, ""},
};

QString genericPath(const QString& path) {
    static const QRegularExpression index(QStringLiteral("/\\d+(/|$)"));
    QString generic = path;
    generic.replace(index, QStringLiteral("/*\\1"));
    return generic;
}

} // namespace

QString rangeText(const scene::Range& range, const QString& unit, int decimals) {
    const QLocale locale;
    QString text = QStringLiteral("%1 – %2").arg(locale.toString(range.min, 'f', decimals),
                                                 locale.toString(range.max, 'f', decimals));
    if (!unit.isEmpty())
        text += QLatin1Char(' ') + unit;
    return text;
}

QString describeIssue(const scene::CaseIssue& issue) {
    const QString path = genericPath(QString::fromStdString(issue.path));
    if (path == QLatin1String("/patient/gravidity") && QString::fromStdString(issue.message).contains("parity"))
        return tr("Gravidity counts every pregnancy, so it cannot be less than the parity.");
    if (path == QLatin1String("/patient/menopausal"))
        return tr("A postmenopausal patient is at least 40 years old, a premenopausal one at most 60.");
    if (path == QLatin1String("/patient/cyclePhase"))
        return tr("Only a premenopausal patient has a cycle phase.");
    if (path == QLatin1String("/anatomy/dimensions/cavityLengthMm") &&
        QString::fromStdString(issue.message).contains("lengthMm"))
        return tr("The cavity must be shorter than the uterus.");
    if (path == QLatin1String("/anatomy/dimensions/cavityWidthMm") &&
        QString::fromStdString(issue.message).contains("widthMm"))
        return tr("The cavity must be narrower than the uterus.");
    if (path == QLatin1String("/pathologies/*/sizeMm"))
        return tr("Myomas are 5 – 100 mm, polyps 3 – 40 mm in size.");
    if (path == QLatin1String("/pathologies/*/id"))
        return tr(
            "An id is 1 – 32 letters, digits, '-' or '_', starts with a letter or digit, and is unique in the case.");
    if (path == QLatin1String("/pathologies"))
        return tr("A case holds at most %1 pathologies.").arg(scene::kMaxPathologies);
    if (path.startsWith(QLatin1String("/scene/materials/"))) {
        // "/scene/materials/<tissue>/<field>": the tissue's own range for its modulus.
        const QStringList parts = path.split(QLatin1Char('/'));
        clinical::Tissue tissue = clinical::Tissue::Myometrium;
        if (parts.size() == 5 && clinical::fromString(parts[3].toStdString(), tissue)) {
            if (parts[4] == QLatin1String("youngsModulusKpa"))
                return tr("Young's modulus must be in the range %1.")
                    .arg(rangeText(scene::youngsModulusRangeKpa(tissue), QStringLiteral("kPa"), 1));
            if (parts[4] == QLatin1String("poissonRatio"))
                return tr("The Poisson ratio must be in the range %1.")
                    .arg(rangeText(scene::limits::kPoissonRatio, {}, 2));
            if (parts[4] == QLatin1String("densityKgPerM3"))
                return tr("The density must be in the range %1.")
                    .arg(rangeText(scene::limits::kDensityKgPerM3, QStringLiteral("kg/m³")));
            if (parts[4] == QLatin1String("heterogeneity"))
                return tr("The heterogeneity must be in the range %1.")
                    .arg(rangeText(scene::limits::kHeterogeneity, {}, 2));
        }
    }
    if (path == QLatin1String("/scene/hydrometraPressureKpa"))
        return tr("The hydrometra pressure must be in the range %1.")
            .arg(rangeText(scene::limits::kHydrometraPressureKpa, QStringLiteral("kPa")));
    for (const Field& field : kFields)
        if (path == QLatin1String(field.path))
            return tr("%1 must be in the range %2.").arg(tr(field.label), rangeText(field.range, tr(field.unit)));
    return tr("This value is not allowed here (%1).").arg(path);
}

std::vector<scene::CaseIssue> issuesUnder(const scene::CaseSpec& spec, const QString& pathPrefix) {
    std::vector<scene::CaseIssue> found;
    const std::string prefix = pathPrefix.toStdString();
    for (auto& issue : scene::checkCase(spec))
        if (issue.path.compare(0, prefix.size(), prefix) == 0 &&
            (issue.path.size() == prefix.size() || issue.path[prefix.size()] == '/' || prefix.empty()))
            found.push_back(std::move(issue));
    return found;
}

void markInvalid(QWidget* field, bool invalid) {
    if (!field)
        return;
    field->setProperty("invalid", invalid);
    field->setStyleSheet(invalid ? QStringLiteral("border: 1px solid #c0392b;") : QString());
}

bool tryEdit(CaseDocument& document, const QString& text, const std::function<void(scene::CaseSpec&)>& change,
             const QString& pathPrefix, QLabel* message, QWidget* field, int mergeKey) {
    scene::CaseSpec candidate = document.spec();
    change(candidate);
    const auto issues = issuesUnder(candidate, pathPrefix);
    if (!issues.empty()) {
        if (message) {
            message->setText(describeIssue(issues.front()));
            message->setToolTip(QString::fromStdString(issues.front().path));
            message->setVisible(true);
        }
        markInvalid(field, true);
        return false;
    }
    if (message) {
        message->clear();
        message->setVisible(false);
    }
    markInvalid(field, false);
    document.edit(text, change, mergeKey);
    return true;
}

} // namespace hs::widgets
