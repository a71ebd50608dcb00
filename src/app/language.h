#pragma once
// The languages Gyre speaks, the user's choice among them (kept in QSettings), and the translators
// that make the program speak it. The translations are compiled into the program (resource prefix
// /i18n); Qt's own, for the standard dialog buttons, come from Qt's translations folder.

#include <QCoreApplication>
#include <QLocale>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

class QTranslator;

namespace gyre::app {

// A language the user can choose: its code (as in the .qm file names: "de", "zh_CN") and its name
// written in itself, as the Preferences dialog lists it.
struct Language {
    QString code;
    QString nativeName;
};

// English first, then the translations Gyre ships.
const std::vector<Language>& availableLanguages();
// Their codes, in the same order.
QStringList languageCodes();

// The language code stored in the settings; empty when the user has chosen none, which means the
// system's language.
QString languageSetting();
// Stores `code`; an empty code removes the choice, so that Gyre follows the system again.
void setLanguageSetting(const QString& code);

// The locale for a language code: the system's for an empty code, nullopt for a code Gyre does not know.
std::optional<QLocale> localeForLanguage(const QString& code);

// The translators of Gyre and of Qt for one locale, installed on the application while this lives.
class Translations {
    Q_DECLARE_TR_FUNCTIONS(gyre::app::Translations)

public:
    // Installs the translations for `code` (see localeForLanguage). An unknown code installs none, so
    // Gyre speaks English, and says so in `warning`.
    explicit Translations(const QString& code);
    ~Translations();
    Translations(const Translations&) = delete;
    Translations& operator=(const Translations&) = delete;

    // Why the requested language is not used; empty when it is.
    const QString& warning() const { return warning_; }

private:
    void install(const QLocale& locale);

    std::vector<std::unique_ptr<QTranslator>> translators_;
    QString warning_;
};

} // namespace gyre::app
