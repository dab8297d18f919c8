// ManualBrowser: the Finbook Manual inside the app (Help → Finbook Manual, F1).
//
// The manual is Markdown pages compiled into the executable (resources/manual/, ":/manual/"),
// with their pictures. The window shows a contents list (titles translated, as far as the
// catalogues go), a search field that narrows the contents to the pages holding every word
// typed (Return opens the first and highlights the words), the page itself with working links
// between pages, and Back and Forward. F1 opens the page of the tool in hand (pageForTool).
#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>

class QLineEdit;
class QListWidget;
class QTextBrowser;
class QToolButton;

namespace finbook::ui {

class ManualBrowser : public QWidget {
    Q_OBJECT
public:
    explicit ManualBrowser(QWidget *parent = nullptr);

    struct Page {
        QString file;  // e.g. "pins.md", in ":/manual/"
        QString title; // translated
    };
    // Every page of the manual, in the contents' order (the first is the contents page).
    static QList<Page> pages();
    // The page about the tool `toolId` ("tool.pin" → "pins.md"); the contents for others.
    static QString pageForTool(const QString &toolId);
    // The Markdown of a page ("" when there is none).
    static QString pageText(const QString &file);

    void openPage(const QString &file);
    QString currentPage() const; // the file name shown, e.g. "bones.md"
    // Narrows the contents to the pages holding every word of `text`; returns how many.
    int search(const QString &text);

    QTextBrowser *text() const { return m_text; }
    QListWidget *contents() const { return m_contents; }
    QLineEdit *searchField() const { return m_search; }

private:
    void showCurrentInContents();
    void openFirstHit();

    QLineEdit *m_search;
    QListWidget *m_contents;
    QTextBrowser *m_text;
    QToolButton *m_back, *m_forward, *m_home;
    QStringList m_words; // the last search, highlighted in the pages it opens
};

} // namespace finbook::ui
