#pragma once
// A widget drawn with OpenGL into a framebuffer of its own, off screen, and shown as an image: the
// viewport's base in place of QOpenGLWidget, with its initializeGL, paintGL and grabFramebuffer. A
// subclass follows its size in resizeEvent; the framebuffer follows it at the next frame.
//
// Why not QOpenGLWidget: a window holding one has Qt compose the whole window through OpenGL at every
// repaint of any of its widgets, which uploads and draws the window's every pixel. On Mesa's llvmpipe
// (no GPU) a repaint of Gyre's 1500 × 950 window took 22 to 52 ms on a busy machine however little had
// changed, while the viewport drew itself in 1 to 4 ms, and held playback to 23 to 57 frames a second. A
// window of raster widgets flushes only what changed. The price here is reading the frame back, 1.4 MB
// at 748 × 460, which on llvmpipe is a copy in memory and on a GPU a wait for the frame to finish;
// README.md gives the figures.
// A QOpenGLWindow in a window container would avoid both, but it is a native window that QWidget::grab does
// not see and that takes the input events from the widget tree.
//
// The context and its offscreen surface are made at the first paint (or makeCurrent) and live as long as
// the widget, wherever it is moved: unlike QOpenGLWidget's, they do not change when a dock floats. Should
// the display refuse them, or the framebuffer at the widget's size, the widget says so in its place and
// the log says which step failed.

#include <QImage>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QSurfaceFormat>
#include <QWidget>

#include <memory>

namespace gyre::app {

class OffscreenGlWidget : public QWidget {
    Q_OBJECT

public:
    OffscreenGlWidget(const QSurfaceFormat& format, QWidget* parent);
    // Subclasses release what they made in their context in their own destructors (makeCurrent first);
    // this one then destroys the framebuffer and the context.
    ~OffscreenGlWidget() override;

    // Draws a frame and returns it; a null image when the display gives no OpenGL context.
    QImage grabFramebuffer();

protected:
    // Makes the context current on the offscreen surface, with the widget's framebuffer bound once the
    // first frame has made it; makes the context first (and calls initializeGL) if need be. False when the
    // display gives no OpenGL context.
    bool makeCurrent();
    void doneCurrent();

    // Called once the context is first current.
    virtual void initializeGL() = 0;
    // Draws the frame, with the framebuffer bound and OpenGL's viewport covering it. The frame is shown as
    // an opaque image: it must leave the framebuffer's alpha at 1.
    virtual void paintGL() = 0;

    void paintEvent(QPaintEvent* event) override;

private:
    // Draws into the framebuffer and reads it into image_; false without a context or a framebuffer.
    bool render();

    QSurfaceFormat format_;
    QOffscreenSurface surface_; // outlives the context made on it
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOpenGLFramebufferObject> framebuffer_;
    QImage image_; // the last frame, kept so that reading back allocates nothing while the size holds
    // Why no frame can be drawn, shown in the widget's place; empty while drawing works.
    QString failure_;
};

} // namespace gyre::app
