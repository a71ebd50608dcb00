#pragma once
// The fit in the status bar: while a fit runs, a progress bar of its rounds (round k of the fit's
// limit) with the largest fragment error so far, and a button to cancel it; at its end, a short
// message in the status bar: converged or why it stopped and the time taken, cancelled, dropped, or
// the error. Hidden while no fit runs. The main window adds it with statusBar()->addPermanentWidget.

#include "app/sketch/fit_controller.h"

#include <QWidget>

class QProgressBar;
class QPushButton;
class QStatusBar;

namespace gyre::app {

class FitProgress : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMessageMilliseconds = 10'000;

    // `statusBar` shows the message at a fit's end.
    FitProgress(FitController& controller, QStatusBar& statusBar, QWidget* parent = nullptr);

    QProgressBar* progressBar() const { return bar_; }

private:
    void showStarted();
    void showProgress(const jobs::FitJobProgress& progress);
    void showEnded(const QString& message);

    QStatusBar& statusBar_;
    QProgressBar* bar_;
    QPushButton* cancelButton_;
};

} // namespace gyre::app
