#include "hs/widgets/panels/ExportPanel.h"

#include "hs/widgets/document/CaseDocument.h"
#include "hs/widgets/jobs/GenerationSession.h"
#include "hs/widgets/panels/SceneWarnings.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProcess>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace hs::widgets {

ExportPanel::ExportPanel(CaseDocument& document, GenerationSession& session, QWidget* parent)
    : QWidget(parent), m_document(document), m_session(session) {
    setObjectName("exportPanel");
    auto* layout = new QVBoxLayout(this);
    auto* group = new QGroupBox(tr("Scene package"), this);
    auto* form = new QFormLayout(group);

    m_folderEdit = new QLineEdit(group);
    m_folderEdit->setObjectName("exportFolderEdit");
    m_folderEdit->setPlaceholderText(tr("Folder of the package"));
    m_folderEdit->setToolTip(tr("The package is written to this folder (created; an existing package is replaced)"));
    m_browseButton = new QPushButton(tr("&Browse..."), group);
    m_browseButton->setObjectName("exportBrowseButton");
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folderEdit, 1);
    folderRow->addWidget(m_browseButton);
    auto* folderLabel = new QLabel(tr("&Folder"), group);
    folderLabel->setBuddy(m_folderEdit);
    form->addRow(folderLabel, folderRow);

    m_zipCheck = new QCheckBox(tr("Also as a .zip"), group);
    m_zipCheck->setObjectName("exportZipCheck");
    form->addRow(QString(), m_zipCheck);
    m_formatsCheck = new QCheckBox(tr("Also the formats of other tools: glTF, Gmsh MSH, OBJ, SOFA"), group);
    m_formatsCheck->setObjectName("exportFormatsCheck");
    form->addRow(QString(), m_formatsCheck);

    m_variantsSpin = new QSpinBox(group);
    m_variantsSpin->setObjectName("exportVariantsSpin");
    m_variantsSpin->setRange(1, 100);
    m_variantsSpin->setToolTip(tr("More than one: a new patient of the same description per variant, each in "
                                  "folder/variant-NNN with its own seed"));
    form->addRow(tr("&Variants"), m_variantsSpin);

    m_exportButton = new QPushButton(tr("&Export"), group);
    m_exportButton->setObjectName("exportButton");
    m_exportButton->setToolTip(tr("Run what is not current, write the package and validate it (Ctrl+E)"));
    form->addRow(m_exportButton);
    layout->addWidget(group);

    m_resultLabel = new QLabel(this);
    m_resultLabel->setObjectName("exportResultLabel");
    m_resultLabel->setWordWrap(true);
    m_resultLabel->setTextFormat(Qt::RichText);
    m_resultLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_resultLabel);

    m_simulatorButton = new QPushButton(tr("Open in &Simulator"), this);
    m_simulatorButton->setObjectName("openInSimulatorButton");
    m_simulatorButton->setEnabled(false);
    layout->addWidget(m_simulatorButton);
    layout->addStretch(1);
    setSimulatorPath(QString());

    connect(m_browseButton, &QPushButton::clicked, this, &ExportPanel::browseRequested);
    connect(m_exportButton, &QPushButton::clicked, this, &ExportPanel::onExport);
    connect(m_simulatorButton, &QPushButton::clicked, this, &ExportPanel::onOpenInSimulator);
    connect(&m_session, &GenerationSession::exported, this, &ExportPanel::onExported);
}

QString ExportPanel::folder() const {
    return m_folderEdit->text();
}

void ExportPanel::setFolder(const QString& folder) {
    m_folderEdit->setText(QDir::toNativeSeparators(folder));
}

void ExportPanel::setSimulatorPath(const QString& path) {
    m_simulatorPath = path;
    m_simulatorButton->setToolTip(path.isEmpty() ? tr("The preview simulator is not installed with this workstation")
                                                 : tr("Start the preview simulator on the exported package"));
    m_simulatorButton->setEnabled(!path.isEmpty() && !m_lastPackage.isEmpty());
}

void ExportPanel::onExport() {
    const QString target = m_folderEdit->text().trimmed();
    if (target.isEmpty()) {
        m_resultLabel->setText(tr("<span style='color:#c0392b'>Choose a folder for the package first.</span>"));
        return;
    }
    m_resultLabel->setText(tr("Exporting..."));
    m_session.exportPackage(QDir::fromNativeSeparators(target), m_zipCheck->isChecked(), m_variantsSpin->value(),
                            m_formatsCheck->isChecked() ? scene::PackageWriteOptions::all()
                                                        : scene::PackageWriteOptions{});
}

void ExportPanel::onExported(const ExportResult& result) {
    const QLocale locale;
    QStringList lines;
    for (const generate::ExportedPackage& p : result.packages) {
        const QString folder = QDir::toNativeSeparators(QFile::decodeName(p.folder.c_str()));
        QString line = tr("<b>%1</b>: valid, %2 files with matching checksums (seed %3).")
                           .arg(folder.toHtmlEscaped())
                           .arg(p.files)
                           .arg(p.seed);
        if (!p.zipPath.empty())
            line += QLatin1Char(' ') +
                    tr("Zipped as %1.").arg(QFileInfo(QFile::decodeName(p.zipPath.c_str())).fileName().toHtmlEscaped());
        const QString diameter = locale.toString(p.scope.scopeDiameterMm, 'f', 1);
        const QString canal = locale.toString(p.scope.canalNarrowestMm, 'f', 2);
        const QString fundus = locale.toString(p.scope.narrowestMm, 'f', 2);
        if (!p.scope.checked)
            line += QLatin1Char(' ') + tr("The scope's passage could not be checked: %1")
                                           .arg(QString::fromStdString(p.scope.uncheckedBecause).toHtmlEscaped());
        else if (!p.scope.passes)
            line += QLatin1Char(' ') + tr("<span style='color:#c0392b'>A %1 mm scope does not pass the cervical canal "
                                          "(narrowest %2 mm).</span>")
                                           .arg(diameter, canal);
        else if (p.scope.reachesFundus)
            line += QLatin1Char(' ') + tr("A %1 mm scope passes the cervical canal (narrowest %2 mm) and reaches the "
                                          "fundus (narrowest %3 mm).")
                                           .arg(diameter, canal, fundus);
        else
            line += QLatin1Char(' ') + tr("A %1 mm scope passes the cervical canal (narrowest %2 mm); a pathology "
                                          "narrows the way to the fundus to %3 mm.")
                                           .arg(diameter, canal, fundus);
        if (!p.warnings.empty())
            line += QLatin1Char(' ') + tr("%n warning(s), also in scene.json:", "", int(p.warnings.size())) +
                    warningsHtml(p.warnings);
        lines << line;
    }
    m_resultLabel->setText(lines.join(QStringLiteral("<br>")));
    m_lastPackage = result.packages.empty() ? QString() : QFile::decodeName(result.packages.front().folder.c_str());
    setSimulatorPath(m_simulatorPath);
}

void ExportPanel::onOpenInSimulator() {
    if (m_simulatorPath.isEmpty() || m_lastPackage.isEmpty())
        return;
    if (!QProcess::startDetached(m_simulatorPath, {m_lastPackage}))
        m_resultLabel->setText(tr("<span style='color:#c0392b'>The simulator could not be started.</span>"));
}

} // namespace hs::widgets
