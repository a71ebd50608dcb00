#include "app/preferences_dialog.h"

#include "app/language.h"
#include "ui_preferences_dialog.h"

namespace gyre::app {

PreferencesDialog::PreferencesDialog(QWidget* parent)
    : QDialog(parent)
    , ui_(std::make_unique<Ui::PreferencesDialog>())
{
    ui_->setupUi(this);
    fillLanguages();
}

PreferencesDialog::~PreferencesDialog() = default;

void PreferencesDialog::fillLanguages()
{
    // Each language is named in itself, so that a user who cannot read the current one finds their own.
    // The item data is the code stored in the settings; the system default stores none.
    ui_->languageBox->addItem(tr("System default"), QString());
    for (const Language& language : availableLanguages())
        ui_->languageBox->addItem(language.nativeName, language.code);
    const int stored = ui_->languageBox->findData(languageSetting());
    ui_->languageBox->setCurrentIndex(stored >= 0 ? stored : 0);
}

void PreferencesDialog::accept()
{
    setLanguageSetting(ui_->languageBox->currentData().toString());
    QDialog::accept();
}

} // namespace gyre::app
