#pragma once
// Gyre's icon, painted in code so the window, the desktop entry and the package share one drawing that
// is sharp at every size: a sphere with an orbit arrow around it, the spin Gyre edits.

#include <QIcon>

#include <array>

class QPainter;

namespace gyre::app {

// The sizes of the hicolor theme's application icons that desktops look up, in pixels.
inline constexpr std::array<int, 9> kAppIconSizes{16, 22, 24, 32, 48, 64, 128, 256, 512};

// Paints the icon into the square (0, 0, size, size) of `painter`'s current coordinates.
void paintAppIcon(QPainter& painter, double size);

// The icon at every size of kAppIconSizes, for the window and the About box.
QIcon appIcon();

} // namespace gyre::app
