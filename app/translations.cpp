#include "translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace finbook::app {

QString installTranslations(QCoreApplication &app, const QString &language)
{
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    if (!language.isEmpty())
        QLocale::setDefault(locale);
    // Beside the executable in a build folder; in an installation, where the install rules put
    // them relative to the executable's folder (so a moved prefix or a DESTDIR still works).
    const QString appDir = QCoreApplication::applicationDirPath();
    const QStringList folders{appDir + QStringLiteral("/translations"),
                              appDir + QStringLiteral("/" FINBOOK_TRANSLATIONS_FROM_BIN),
                              QStringLiteral(":/translations")};
    auto *finbook = new QTranslator(&app);
    for (const QString &folder : folders) {
        if (finbook->load(locale, QStringLiteral("finbook"), QStringLiteral("_"), folder)) {
            QCoreApplication::installTranslator(finbook);
            auto *qt = new QTranslator(&app);
            if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                         QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
                QCoreApplication::installTranslator(qt);
            return finbook->language();
        }
    }
    // No catalogue for the language: English, with English plural forms ("2 frames", not the
    // source text's "2 frame(s)").
    for (const QString &folder : folders) {
        if (finbook->load(QLocale(QLocale::English), QStringLiteral("finbook"), QStringLiteral("_"),
                          folder)) {
            QCoreApplication::installTranslator(finbook);
            return {};
        }
    }
    delete finbook;
    return {};
}

} // namespace finbook::app
