// Real X input for the render tests: key presses, pointer motion and buttons sent through the X
// server's XTEST extension on a connection of its own, so they reach Qt as a keyboard's and a
// mouse's do (the platform's key mapping, the native GL window's input pass-through, shortcuts).
#pragma once

#include <QPoint>
#include <QTest>
#include <QWidget>
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>
#undef None // X11's macros, which would hide enumerators of the same names
#undef Bool
#undef Status

#include <initializer_list>
#include <iterator>

namespace octaclay::testing {

class XTestInput {
public:
  XTestInput() : display_(XOpenDisplay(nullptr)) {}
  ~XTestInput() {
    if (display_) XCloseDisplay(display_);
  }
  XTestInput(const XTestInput&) = delete;
  XTestInput& operator=(const XTestInput&) = delete;

  bool ready() const {
    int event = 0, error = 0, major = 0, minor = 0;
    return display_ && XTestQueryExtension(display_, &event, &error, &major, &minor);
  }
  void moveTo(QPoint global) {
    XTestFakeMotionEvent(display_, -1, global.x(), global.y(), CurrentTime);
    settle();
  }
  void button(unsigned int button, bool down) {
    XTestFakeButtonEvent(display_, button, down, CurrentTime);
    settle();
  }
  void click(unsigned int button) {
    this->button(button, true);
    this->button(button, false);
  }
  void key(KeySym symbol, bool down) {
    XTestFakeKeyEvent(display_, XKeysymToKeycode(display_, symbol), down, CurrentTime);
    settle();
  }
  /// The keys held in order, released in reverse: a chord such as Alt+click's Alt or Ctrl+Z.
  void press(std::initializer_list<KeySym> chord) {
    for (KeySym k : chord)
      key(k, true);
    for (auto k = std::rbegin(chord); k != std::rend(chord); ++k)
      key(*k, false);
  }
  /// Each character typed as its own key: digits, '.', '-', lower-case letters.
  void type(const char* text) {
    for (const char* c = text; *c; ++c) {
      const KeySym symbol = *c == '.'   ? XK_period
                            : *c == '-' ? XK_minus
                                        : static_cast<KeySym>(static_cast<unsigned char>(*c));
      press({symbol});
    }
  }

private:
  void settle() {
    XFlush(display_);
    QTest::qWait(30);
  }
  Display* display_;
};

/// Makes w the active window as a click on its title would: with no window manager under Xvfb
/// nothing else gives a new window the X input focus.
inline bool activateWindow(QWidget& w) {
  w.activateWindow();
  w.raise();
  return QTest::qWaitForWindowActive(&w);
}

} // namespace octaclay::testing
