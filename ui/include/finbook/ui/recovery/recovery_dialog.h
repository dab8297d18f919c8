// The dialog at start-up that offers the recovery copies a crashed or killed Finbook left:
// one row per copy with its thumbnail, name, when it was taken and how many frames it holds.
#pragma once

#include <finbook/model/recovery/recovery_store.h>

#include <QDialog>

class QListWidget;

namespace finbook::ui {

class RecoveryDialog : public QDialog {
    Q_OBJECT
public:
    enum class Action { Restore, Discard, Later };

    RecoveryDialog(const std::vector<model::RecoveryCopy> &copies, QWidget *parent = nullptr);

    // After exec(): what the user chose, and for which copy (an index into `copies`).
    Action action() const { return m_action; }
    int chosen() const;

    // "walk.finbook — 23 Nov 2024 10:31 — 14 frames", as a row shows it.
    static QString describe(const model::RecoveryCopy &copy);

private:
    void finish(Action action);

    QListWidget *m_list;
    Action m_action = Action::Later;
};

} // namespace finbook::ui
