// Action texts outside menus: the mnemonic goes in both its Western ("&Open") and its
// bracketed Japanese form ("開く(&O)"), and toolbar buttons follow an action's text without it.
#include <finbook/ui/i18n/action_text.h>

#include <QAction>
#include <QToolBar>
#include <QToolButton>
#include <QtTest>

using namespace finbook;

class TestActionText : public QObject {
    Q_OBJECT
private slots:
    void withoutMnemonic_data();
    void withoutMnemonic();
    void toolbarButtonsFollowTheText();
    void explicitIconTextAndToolTipStay();
    void westernTextsAreLeftToQt();
};

void TestActionText::withoutMnemonic_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("plain");
    QTest::addColumn<QString>("iconText");
    QTest::newRow("western") << "&Open..."
                             << "Open..."
                             << "Open";
    QTest::newRow("inside a word") << "Save &As..."
                                   << "Save As..."
                                   << "Save As";
    QTest::newRow("literal ampersand") << "Black && White"
                                       << "Black & White"
                                       << "Black & White";
    QTest::newRow("bracketed") << QString::fromUtf8("開く(&O)...") << QString::fromUtf8("開く...")
                               << QString::fromUtf8("開く");
    QTest::newRow("bracketed after a space")
        << QString::fromUtf8("実際のサイズ (100%) (&A)") << QString::fromUtf8("実際のサイズ (100%)")
        << QString::fromUtf8("実際のサイズ (100%)");
    QTest::newRow("bracketed mid-text") << QString::fromUtf8("元に戻す(&U) ストロークを描画")
                                        << QString::fromUtf8("元に戻す ストロークを描画")
                                        << QString::fromUtf8("元に戻す ストロークを描画");
    QTest::newRow("brackets that are no mnemonic") << "Stiffer (+1 Pass)"
                                                   << "Stiffer (+1 Pass)"
                                                   << "Stiffer (+1 Pass)";
    QTest::newRow("recent file") << "&1 walk.finbook"
                                 << "1 walk.finbook"
                                 << "1 walk.finbook";
    QTest::newRow("empty") << QString() << QString() << QString();
}

void TestActionText::withoutMnemonic()
{
    QFETCH(QString, text);
    QFETCH(QString, plain);
    QFETCH(QString, iconText);
    QCOMPARE(ui::withoutMnemonic(text), plain);
    QCOMPARE(ui::plainIconText(text), iconText);
}

void TestActionText::toolbarButtonsFollowTheText()
{
    QToolBar bar;
    auto *action = new QAction(QString::fromUtf8("保存(&S)"), &bar);
    bar.addAction(action);
    auto *button = qobject_cast<QToolButton *>(bar.widgetForAction(action));
    QVERIFY(button);
    // Qt's own derivation keeps the letter: this is what the helper is for.
    QCOMPARE(button->text(), QString::fromUtf8("保存(S)"));

    ui::keepIconTextsPlain(&bar);
    QCOMPARE(action->iconText(), QString::fromUtf8("保存"));
    QCOMPARE(action->toolTip(), QString::fromUtf8("保存"));
    QCOMPARE(button->text(), QString::fromUtf8("保存"));
    QCOMPARE(action->text(), QString::fromUtf8("保存(&S)")); // menus keep the mnemonic

    // Later text changes (Play -> Pause, Undo's command name) are followed too.
    action->setText(QString::fromUtf8("一時停止(&P)"));
    QCOMPARE(button->text(), QString::fromUtf8("一時停止"));
    QCOMPARE(action->toolTip(), QString::fromUtf8("一時停止"));
}

void TestActionText::explicitIconTextAndToolTipStay()
{
    QAction action(QString::fromUtf8("選択範囲をオブジェクトへ移動(&S)"));
    action.setIconText(QString::fromUtf8("移動先"));
    action.setToolTip(QString::fromUtf8("選択したストロークを別のオブジェクトへ移動"));
    ui::keepIconTextPlain(&action);
    QCOMPARE(action.iconText(), QString::fromUtf8("移動先"));
    QCOMPARE(action.toolTip(), QString::fromUtf8("選択したストロークを別のオブジェクトへ移動"));
    action.setText(QString::fromUtf8("移動(&M)"));
    QCOMPARE(action.iconText(), QString::fromUtf8("移動先"));
}

void TestActionText::westernTextsAreLeftToQt()
{
    QAction action(QStringLiteral("&Open..."));
    ui::keepIconTextPlain(&action);
    QCOMPARE(action.iconText(), QStringLiteral("Open"));
    // Still derived by Qt (nothing set explicitly), so a new text changes it.
    action.setText(QStringLiteral("&Close"));
    QCOMPARE(action.iconText(), QStringLiteral("Close"));
    QCOMPARE(action.toolTip(), QStringLiteral("Close"));
}

QTEST_MAIN(TestActionText)
#include "tst_action_text.moc"
