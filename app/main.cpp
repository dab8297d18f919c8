#include "cli.h"
#include "cli_export.h"
#include "instance/instance_server.h"
#include "instance/window_list.h"
#include "native_names.h"
#include "test_hooks.h"
#include "translations.h"

#include <finbook/model/io/printable_text.h>
#include <finbook/ui/window/main_window.h>
#include <finbook/ui/window/welcome_dialog.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace {

// Qt's French and Japanese catalogues lack the help options' texts. Finbook's catalogue holds
// them under Qt's context; QCoreApplication::translate falls back to it when Qt's has none.
[[maybe_unused]] constexpr const char *kQtHelpTexts[] = {
    QT_TRANSLATE_NOOP("QCommandLineParser", "Displays help on commandline options."),
    QT_TRANSLATE_NOOP("QCommandLineParser", "Displays help including Qt specific options.")};

struct Options {
    QString language;
    QStringList positional;
};

// Parses before any QApplication exists so `info`/`export` never need a display.
// Returns an exit code to stop with, or -1 to continue. Prints help, the version or the
// error only when `print` is set (main() first installs the translator for that).
int parseCommandLine(const QStringList &arguments, Options &options, bool print = true)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "CommandLine",
        "Finbook, a flipbook animation editor.\n\n"
        "  finbook [FILE]               open FILE in the editor\n"
        "  finbook info FILE            print a JSON summary of FILE\n"
        "  finbook export FILE OUTDIR   render every frame to OUTDIR/frame_0001.png ...\n"
        "  finbook export FILE OUT      export to OUT.gif, .mp4, .webm, .apng or .html\n"
        "  finbook export FILE OUT.obj --frame N   frame N as a 3D model (OUT.obj, OUT.mtl)\n"
        "  finbook export FILE OUT.glb --frame N   frame N as a 3D model (glTF binary)\n"
        "  finbook export FILE... --format F --out-dir DIR   export several files\n"
        "  finbook thumbnail FILE OUT.png SIZE   write the first frame as a PNG of at most SIZE "
        "px"));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate("CommandLine",
                                    "Use LANGUAGE (e.g. de, en, fr, ja) instead of the system's."),
        QStringLiteral("LANGUAGE"));
    parser.addOption(lang);
    finbook::app::addExportOptions(parser);
    parser.addPositionalArgument(QStringLiteral("args"),
                                 QCoreApplication::translate("CommandLine", "FILE, or a command."),
                                 QStringLiteral("[FILE | info FILE | export FILE... OUT]"));
    QString outText, errText;
    QTextStream out(&outText), err(&errText);
    const auto finish = [&](finbook::app::ExitCode code) {
        if (print) {
            QTextStream(stdout) << outText;
            QTextStream(stderr) << errText;
        }
        return int(code);
    };
    const QString seeHelp =
        QCoreApplication::translate("CommandLine", "see finbook --help", "after an error");
    if (!parser.parse(arguments)) {
        // Qt's message ends a sentence ('.', or U+3002 in Japanese); the translated pattern ends it
        // after the hint instead, with the punctuation the language uses.
        QString error = finbook::model::printableText(parser.errorText().simplified());
        if (error.endsWith(QLatin1Char('.')) || error.endsWith(QChar(0x3002)))
            error.chop(1);
        err << QCoreApplication::translate("CommandLine", "%1; %2.",
                                           "an argument error from Qt, then \"see finbook --help\"")
                   .arg(error, seeHelp)
            << Qt::endl;
        return finish(finbook::app::ExitCode::BadInput);
    }
    if (parser.isSet(help) || parser.isSet(QStringLiteral("help-all"))) {
        // The usage line names the program as it was typed (a path); say "finbook".
        QString text =
            parser.helpText().replace(QLatin1String("<executable_name>"), QLatin1String("finbook"));
        if (QCoreApplication::instance())
            text.replace(QStringLiteral(": ") + QCoreApplication::arguments().value(0) +
                             QLatin1Char(' '),
                         QStringLiteral(": finbook "));
        out << text;
        return finish(finbook::app::ExitCode::Ok);
    }
    if (parser.isSet(version)) {
        out << "finbook " << finbook::app::finbookVersion() << Qt::endl;
        return finish(finbook::app::ExitCode::Ok);
    }
    options.language = parser.value(lang);
    options.positional = parser.positionalArguments();
    const bool headless = finbook::app::isHeadlessCommand(options.positional);
    if (headless) {
        // The option words go before a "--", so a file named "-x.finbook" (given after "--")
        // stays a file name when `export` parses its arguments again.
        const QStringList words = finbook::app::exportOptionArguments(parser);
        if (options.positional.first() == QLatin1String("export"))
            options.positional = QStringList{options.positional.first()} + words +
                                 QStringList{QStringLiteral("--")} + options.positional.mid(1);
        else
            options.positional += words;
    }
    // More than one word that is not info/export is a mistyped command, not a file list.
    if (!headless && options.positional.size() > 1) {
        err << QCoreApplication::translate("CommandLine", "Unknown command \"%1\"; %2.")
                   .arg(finbook::model::printableText(options.positional.first()), seeHelp)
            << Qt::endl;
        return finish(finbook::app::ExitCode::BadInput);
    }
    return -1;
}

// The value of --lang, found without the parser (which may be refusing other arguments).
QString languageArgument(const QStringList &arguments)
{
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == QLatin1String("--lang") && i + 1 < arguments.size())
            return arguments[i + 1];
        if (arguments[i].startsWith(QLatin1String("--lang=")))
            return arguments[i].mid(7);
    }
    return {};
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication::setApplicationName(QStringLiteral("Finbook"));
    QCoreApplication::setOrganizationName(QStringLiteral("Finbook"));
    QCoreApplication::setApplicationVersion(finbook::app::finbookVersion());

    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    finbook::app::rememberRawArguments(argc, argv);

    // Parse before any application object exists: --help, --version, bad arguments, `info`
    // and `export` must all work without a display.
    Options options;
    if (parseCommandLine(arguments, options, false) >= 0) {
        // Help, version and argument errors are for people: say them in their language.
        QCoreApplication app(argc, argv);
        finbook::app::installTranslations(app, languageArgument(arguments));
        return parseCommandLine(arguments, options);
    }

    if (finbook::app::isHeadlessCommand(options.positional)) {
        // Rendering strokes into a QImage needs no platform plugin; a QGuiApplication would
        // load one and could print its own warnings, breaking the one-line-on-stderr promise.
        // A reference may be an SVG with text, though, and text needs the font database,
        // which aborts the process without a QGuiApplication: an export that includes the
        // reference gets one, on the offscreen platform (no display), with Qt's own
        // messages kept off stderr.
        QTextStream out(stdout), err(stderr);
        if (finbook::app::headlessCommandRendersText(options.positional)) {
            const QByteArray platform = qgetenv("QT_QPA_PLATFORM");
            qputenv("QT_QPA_PLATFORM", "offscreen");
            qInstallMessageHandler(finbook::app::quietQtMessages);
            QGuiApplication app(argc, argv);
            if (platform.isNull())
                qunsetenv("QT_QPA_PLATFORM");
            else
                qputenv("QT_QPA_PLATFORM", platform);
            finbook::app::installTranslations(app, options.language);
            return finbook::app::runHeadlessCommand(options.positional, out, err);
        }
        QCoreApplication app(argc, argv);
        finbook::app::installTranslations(app, options.language);
        return finbook::app::runHeadlessCommand(options.positional, out, err);
    }

    QApplication app(argc, argv);
    // The desktop entry's id: Wayland compositors match windows to the entry (and its icon).
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.finbook.Finbook"));
    finbook::app::installTranslations(app, options.language);
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/finbook.svg")));

    const bool scripted = finbook::app::testHooksRequested();
    // A Finbook already running opens the file in a window of its own (instance/); this one
    // then has nothing to do. --lang asks for a Finbook of its own in that language.
    finbook::app::InstanceServer instance;
    if (!scripted && options.language.isEmpty()) {
        if (finbook::app::forwardToRunningInstance(options.positional))
            return 0;
        instance.listen();
    }
    std::unique_ptr<finbook::ui::MainWindow> window =
        scripted ? std::make_unique<finbook::app::ScriptedMainWindow>()
                 : std::make_unique<finbook::ui::MainWindow>();
    window->show();
    if (!options.positional.isEmpty())
        window->openFile(options.positional.first());
    finbook::app::WindowList windows;
    windows.add(window.get());
    QObject::connect(&instance, &finbook::app::InstanceServer::openRequested, &windows,
                     &finbook::app::WindowList::open);
    // Once the window is up: what crashed Finbooks left is offered (or the test hooks run).
    // The first start (with no file to open) shows the welcome page.
    const bool welcome = !scripted && options.positional.isEmpty() &&
                         finbook::ui::WelcomeDialog::shouldShowAtStart();
    QTimer::singleShot(0, window.get(), [w = window.get(), scripted, welcome] {
        if (scripted) {
            static_cast<finbook::app::ScriptedMainWindow *>(w)->runHooks();
            return;
        }
        w->offerRecovery();
        if (welcome && w->document()->undoStack()->count() == 0 && w->filePath().isEmpty())
            w->showWelcome();
    });
    return app.exec();
}
