#include "app/language.h"

#include "io/scene_worker.h"

#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace gyre::app {

namespace {

const char* const kLanguageKey = "language";

} // namespace

const std::vector<Language>& availableLanguages()
{
    static const std::vector<Language> languages{
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("zh_CN"), QStringLiteral("简体中文")},
    };
    return languages;
}

QStringList languageCodes()
{
    QStringList codes;
    for (const Language& language : availableLanguages())
        codes.append(language.code);
    return codes;
}

QString languageSetting() { return QSettings().value(kLanguageKey).toString(); }

void setLanguageSetting(const QString& code)
{
    QSettings settings;
    if (code.isEmpty())
        settings.remove(kLanguageKey);
    else
        settings.setValue(kLanguageKey, code);
}

std::optional<QLocale> localeForLanguage(const QString& code)
{
    if (code.isEmpty())
        return QLocale::system();
    if (!languageCodes().contains(code))
        return std::nullopt;
    return QLocale(code);
}

Translations::Translations(const QString& code)
{
    const std::optional<QLocale> locale = localeForLanguage(code);
    if (!locale) {
        warning_ = tr("Gyre does not speak the language \"%1\" and speaks English instead.").arg(code);
        return;
    }
    install(*locale);
}

Translations::~Translations()
{
    io::setSceneWorkerLocale(QLocale::c());
    for (const std::unique_ptr<QTranslator>& translator : translators_)
        QCoreApplication::removeTranslator(translator.get());
}

void Translations::install(const QLocale& locale)
{
    // QTranslator::load tries the locale's UI languages in turn (zh_CN, then zh, ...); a locale Gyre
    // has no translation for, English among them, finds no file and leaves the program in English.
    const auto load = [this, &locale](const QString& name, const QString& directory) {
        auto translator = std::make_unique<QTranslator>();
        if (!translator->load(locale, name, QStringLiteral("_"), directory))
            return;
        QCoreApplication::installTranslator(translator.get());
        translators_.push_back(std::move(translator));
    };
    load(QStringLiteral("qtbase"), QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    load(QStringLiteral("gyre"), QStringLiteral(":/i18n"));
    // The scene worker's messages in the same language.
    io::setSceneWorkerLocale(locale);
}

} // namespace gyre::app
