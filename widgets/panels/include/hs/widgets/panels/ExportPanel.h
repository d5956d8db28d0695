#pragma once
/// The Export panel: where the scene package goes (a folder, optionally also a .zip), how many variants (each a new
/// patient of the same description, with a seed derived from the case's), Export to run every stage that is not
/// current and write, verify and check the package(s) in the background, and the validation result of each package
/// (files and checksums, the scene's warnings, whether a 2.9 mm scope reaches the fundus). "Open in Simulator"
/// starts the preview simulator on the package when it is installed beside the workstation.

#include <QString>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace hs::widgets {

class CaseDocument;
class GenerationSession;
struct ExportResult;

class ExportPanel : public QWidget {
    Q_OBJECT

public:
    ExportPanel(CaseDocument& document, GenerationSession& session, QWidget* parent = nullptr);

    QString folder() const;
    void setFolder(const QString& folder);
    /// The preview simulator's executable; empty when it is not installed (the button is then disabled).
    void setSimulatorPath(const QString& path);
    /// The package written last; empty before the first export.
    QString lastPackage() const { return m_lastPackage; }

signals:
    /// Browse was clicked: the window asks for a folder (through its file dialog seam) and calls setFolder().
    void browseRequested();

private:
    void onExport();
    void onExported(const ExportResult& result);
    void onOpenInSimulator();

    CaseDocument& m_document;
    GenerationSession& m_session;
    QString m_simulatorPath;
    QString m_lastPackage;

    QLineEdit* m_folderEdit = nullptr;
    QPushButton* m_browseButton = nullptr;
    QCheckBox* m_zipCheck = nullptr;
    QCheckBox* m_formatsCheck = nullptr; ///< also glTF, MSH, OBJ and SOFA
    QSpinBox* m_variantsSpin = nullptr;
    QPushButton* m_exportButton = nullptr;
    QLabel* m_resultLabel = nullptr;
    QPushButton* m_simulatorButton = nullptr;
};

} // namespace hs::widgets
