#include "cli.h"
#include "translations.h"

#include <finbook/ui/main_window.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QTextStream>

#include <cstdio>
#include <memory>

namespace {

struct Options {
    QString language;
    QStringList positional;
};

// Parses before any QApplication exists so `info`/`export` never need a display.
// Returns an exit code to stop with, or -1 to continue.
int parseCommandLine(const QStringList &arguments, Options &options)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "CommandLine", "Finbook, a flipbook animation editor.\n\n"
                       "  finbook [FILE]               open FILE in the editor\n"
                       "  finbook info FILE            print a JSON summary of FILE\n"
                       "  finbook export FILE OUTDIR   render every frame to OUTDIR/frame_0001.png ..."));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QCommandLineOption lang(
        QStringLiteral("lang"),
        QCoreApplication::translate("CommandLine", "Use LANGUAGE (e.g. de, en) instead of the system's."),
        QStringLiteral("LANGUAGE"));
    parser.addOption(lang);
    parser.addPositionalArgument(QStringLiteral("args"),
                                 QCoreApplication::translate("CommandLine", "FILE, or a command."),
                                 QStringLiteral("[FILE | info FILE | export FILE OUTDIR]"));
    QTextStream out(stdout), err(stderr);
    if (!parser.parse(arguments)) {
        err << parser.errorText() << Qt::endl;
        return int(finbook::app::ExitCode::BadInput);
    }
    if (parser.isSet(help)) {
        out << parser.helpText();
        return 0;
    }
    if (parser.isSet(version)) {
        out << "finbook " << FINBOOK_VERSION << Qt::endl;
        return 0;
    }
    options.language = parser.value(lang);
    options.positional = parser.positionalArguments();
    const bool headless = finbook::app::isHeadlessCommand(options.positional);
    if (!headless && options.positional.size() > 1) {
        err << QCoreApplication::translate("CommandLine", "Too many arguments; see finbook --help.")
            << Qt::endl;
        return int(finbook::app::ExitCode::BadInput);
    }
    return -1;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication::setApplicationName(QStringLiteral("Finbook"));
    QCoreApplication::setOrganizationName(QStringLiteral("Finbook"));
    QCoreApplication::setApplicationVersion(QStringLiteral(FINBOOK_VERSION));

    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);

    // Parse before any application object exists: --help, --version, bad arguments, `info`
    // and `export` must all work without a display.
    Options options;
    if (const int code = parseCommandLine(arguments, options); code >= 0)
        return code;

    if (finbook::app::isHeadlessCommand(options.positional)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        QGuiApplication app(argc, argv);
        finbook::app::installTranslations(app, options.language);
        QTextStream out(stdout), err(stderr);
        return finbook::app::runHeadlessCommand(options.positional, out, err);
    }

    QApplication app(argc, argv);
    finbook::app::installTranslations(app, options.language);
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/finbook.svg")));

    finbook::ui::MainWindow window;
    window.show();
    if (!options.positional.isEmpty())
        window.openFile(options.positional.first());
    return app.exec();
}
