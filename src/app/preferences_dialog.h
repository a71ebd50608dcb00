#pragma once
// Edit > Preferences: the settings that are the user's, not the document's. They are stored in
// QSettings when the dialog is accepted, and are no undo step.

#include <QDialog>

#include <memory>

namespace Ui {
class PreferencesDialog;
}

namespace gyre::app {

class PreferencesDialog : public QDialog {
    Q_OBJECT

public:
    // Shows the stored settings.
    explicit PreferencesDialog(QWidget* parent = nullptr);
    ~PreferencesDialog() override;

    // Stores the settings shown, and closes.
    void accept() override;

private:
    void fillLanguages();

    std::unique_ptr<Ui::PreferencesDialog> ui_;
};

} // namespace gyre::app
