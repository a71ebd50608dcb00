#pragma once
// Edit ▸ Copy and Edit ▸ Paste of keys and poses (model/key_clipboard.h for the text they carry).
//
// Copy with keys selected copies them, of every selected object, with their objects' names and
// times relative to the first. Copy with no key selected copies the active object's pose at the
// current time. Paste puts copied keys at the current time: onto the active object when one
// object's keys were copied, else onto the selected objects of the same names; a pose becomes a key
// at the current time on every selected object. Pasted keys replace keys at the same times, are
// selected, and are one undo step. Text that is not Gyre's keys, or keys the objects cannot take,
// paste nothing and say why in the status bar.

#include "app/selection.h"
#include "model/document.h"

#include <QObject>

class QAction;
class QStatusBar;

namespace gyre::app {

class KeyClipboardActions : public QObject {
    Q_OBJECT

public:
    KeyClipboardActions(model::Document& document, Selection& selection, QAction* copy, QAction* paste,
                        QStatusBar* statusBar, QObject* parent = nullptr);

    void copy();
    void paste();

private:
    void updateActions();
    void tell(const QString& message);

    model::Document& document_;
    Selection& selection_;
    QAction* copy_;
    QAction* paste_;
    QStatusBar* statusBar_;
};

} // namespace gyre::app
