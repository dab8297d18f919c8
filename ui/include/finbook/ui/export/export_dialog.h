// File > Export...: format, frames, scale, background, frame rate and the output path, then a
// progress bar with Cancel while an ExportJob works on a worker thread.
//
// The dialog snapshots the document when the export starts. Files already at the target are
// replaced only after confirmOverwrite() says yes; failures reach the user through
// showFailure() with ffmpeg's last lines as details. Both are virtual so tests can answer.
// A successful export closes the dialog (accepted); summary() then says what was written.
// The 3D model (OBJ) exports the current frame only (setCurrentFrame): the range, scale,
// background and rate fields are disabled for it, and the status line says so.
#pragma once

#include <finbook/model/export/export_options.h>

#include <QDialog>

#include <memory>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace finbook::model {
class Document;
}

namespace finbook::ui {

class ColorButton;
class ExportJob;

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    enum class Range { PlayRange, AllFrames, Custom };
    enum class Background { Document, Transparent, Colour };

    // `documentPath` (may be empty) suggests the output name and folder.
    ExportDialog(const model::Document &document, const QString &documentPath,
                 QWidget *parent = nullptr);
    ~ExportDialog() override;

    // What the fields say.
    model::ExportOptions options() const;
    void setFormat(model::ExportFormat format);
    void setTarget(const QString &path);
    // The frame the editor shows (index in the current layer): a 3D model export writes the
    // picture of the shot showing its first tick.
    void setCurrentFrame(int index);
    bool isExporting() const;
    QString summary() const { return m_summary; }
    // The files the finished export wrote (empty before that).
    const QStringList &writtenFiles() const { return m_written; }

    QComboBox *formatBox() const { return m_format; }
    QLineEdit *targetEdit() const { return m_target; }
    QComboBox *rangeBox() const { return m_range; }
    QSpinBox *firstFrameBox() const { return m_first; }
    QSpinBox *lastFrameBox() const { return m_last; }
    QDoubleSpinBox *scaleBox() const { return m_scale; }
    QComboBox *backgroundBox() const { return m_background; }
    ColorButton *colourButton() const { return m_colour; }
    QSpinBox *fpsBox() const { return m_fps; }
    QCheckBox *loopBox() const { return m_loop; }
    QCheckBox *perDrawingBox() const { return m_perDrawing; }
    QCheckBox *includeReferenceBox() const { return m_includeReference; }
    QProgressBar *progressBar() const { return m_progress; }
    QPushButton *exportButton() const { return m_exportButton; }
    QPushButton *cancelButton() const { return m_cancelButton; }
    ExportJob *job() const { return m_job.get(); }
    // The pictures the shot has (composed from every layer; one layer: its frames).
    int shotFrameCount() const;

public slots:
    void startExport();
    void cancelExport();
    void reject() override; // Close/Escape while exporting cancels the export first

signals:
    void exportStarted();
    void exportFinished(bool ok);

protected:
    virtual bool confirmOverwrite(const QStringList &existing);
    // An export beyond the default size limits (model::checkExportSize) runs only after a yes.
    virtual bool confirmLargeExport(const QString &message);
    virtual void showFailure(const QString &message, const QString &detail);
    virtual QString askTargetPath();

private:
    void buildForm();
    void layOut();
    void connectFields();
    void updateFields();
    void formatChanged();
    void jobFinished(bool ok, const model::ExportError &error, const QStringList &files);
    void setRunning(bool running);

    const model::Document &m_doc;
    QString m_documentPath;
    int m_currentFrame = 0;
    QComboBox *m_format = nullptr;
    QLineEdit *m_target = nullptr;
    QPushButton *m_browse = nullptr;
    QComboBox *m_range = nullptr;
    QSpinBox *m_first = nullptr;
    QSpinBox *m_last = nullptr;
    QDoubleSpinBox *m_scale = nullptr;
    QLabel *m_pixels = nullptr;
    QComboBox *m_background = nullptr;
    ColorButton *m_colour = nullptr;
    QSpinBox *m_fps = nullptr;
    QCheckBox *m_loop = nullptr;
    QCheckBox *m_perDrawing = nullptr;
    QCheckBox *m_includeReference = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QPushButton *m_exportButton = nullptr;
    QPushButton *m_cancelButton = nullptr;
    QPushButton *m_closeButton = nullptr;
    std::unique_ptr<ExportJob> m_job;
    QString m_summary;
    QStringList m_written;
};

} // namespace finbook::ui
