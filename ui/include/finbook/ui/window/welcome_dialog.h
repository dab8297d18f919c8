// WelcomeDialog: the first window a new user sees (at Finbook's first start, and File →
// Welcome): New, Open, Open the Example, the recent files, and a one-page "draw — bend — play"
// walkthrough that links to the manual. It only asks: the main window does what is chosen.
#pragma once

#include <QDialog>

class QCheckBox;
class QListWidget;
class QPushButton;
class QTextBrowser;

namespace finbook::ui {

class WelcomeDialog : public QDialog {
    Q_OBJECT
public:
    WelcomeDialog(const QStringList &recentFiles, QWidget *parent = nullptr);

    // Shown at start the first time Finbook runs, and then at every start only if the user
    // asked for it (the check box); recorded in QSettings.
    static bool shouldShowAtStart();
    static void markShown();

    QListWidget *recentList() const { return m_recent; }
    QTextBrowser *walkthrough() const { return m_walkthrough; }

signals:
    void newRequested();
    void openRequested();
    void exampleRequested();
    void recentRequested(const QString &path);
    void manualRequested(const QString &page);

private:
    QPushButton *m_new, *m_open, *m_example, *m_manual;
    QListWidget *m_recent;
    QTextBrowser *m_walkthrough;
    QCheckBox *m_atStart;
};

} // namespace finbook::ui
