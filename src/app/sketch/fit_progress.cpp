#include "app/sketch/fit_progress.h"

#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

namespace gyre::app {

namespace {

constexpr int kBarWidth = 320;

} // namespace

FitProgress::FitProgress(FitController& controller, QStatusBar& statusBar, QWidget* parent)
    : QWidget(parent)
    , statusBar_(statusBar)
    , bar_(new QProgressBar(this))
    , cancelButton_(new QPushButton(tr("Cancel"), this))
{
    bar_->setObjectName(QStringLiteral("fitProgressBar"));
    bar_->setFixedWidth(kBarWidth);
    bar_->setTextVisible(true);
    cancelButton_->setObjectName(QStringLiteral("cancelFit"));
    cancelButton_->setToolTip(tr("Stop the fit; the motion stays as it is"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(bar_);
    layout->addWidget(cancelButton_);

    connect(cancelButton_, &QPushButton::clicked, &controller, &FitController::cancel);
    connect(&controller, &FitController::fitStarted, this, &FitProgress::showStarted);
    connect(&controller, &FitController::progressed, this, &FitProgress::showProgress);
    connect(&controller, &FitController::fitEnded, this, &FitProgress::showEnded);
    setVisible(controller.isFitting());
}

void FitProgress::showStarted()
{
    // Busy until the first round reports how many rounds there may be.
    bar_->setRange(0, 0);
    bar_->setFormat(tr("Fitting…"));
    statusBar_.clearMessage();
    show();
}

void FitProgress::showProgress(const jobs::FitJobProgress& progress)
{
    bar_->setRange(0, progress.maxRounds);
    bar_->setValue(progress.round);
    bar_->setFormat(progress.largestRelativeError
                        ? tr("Fit: round %v of %m, largest relative error %1").arg(*progress.largestRelativeError, 0, 'g', 3)
                        : tr("Fit: round %v of %m"));
}

void FitProgress::showEnded(const QString& message)
{
    hide();
    statusBar_.showMessage(message, kMessageMilliseconds);
}

} // namespace gyre::app
