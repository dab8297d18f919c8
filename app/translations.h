#pragma once

#include <QString>

class QCoreApplication;

namespace finbook::app {

// Installs Finbook's and Qt's translators for `language` ("de", "en", …; empty = the
// system locale). Returns the language actually loaded, empty when falling back to English.
QString installTranslations(QCoreApplication &app, const QString &language);

} // namespace finbook::app
