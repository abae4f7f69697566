// Real X input for render tests: XTEST events through the X server, as a mouse and keyboard
// give them (not events sent to a widget, which skip the platform's key mapping and the native
// GL window's routing). The same as real_input_render_test's, shared for newer tests.
#pragma once

#include <QTest>
#include <QWidget>
#include <X11/XKBlib.h>
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>

#include <atomic>
#include <chrono>
#include <initializer_list>
#include <iterator>
#include <thread>

namespace octaclay::app::testing {

/// An X connection of its own: XTEST input goes through the server to Qt's connection.
class FakeInput {
public:
  FakeInput() : display_(XOpenDisplay(nullptr)) {}
  ~FakeInput() {
    if (display_) XCloseDisplay(display_);
  }
  FakeInput(const FakeInput&) = delete;
  FakeInput& operator=(const FakeInput&) = delete;

  bool ready() const {
    int event = 0, error = 0, major = 0, minor = 0;
    return display_ && XTestQueryExtension(display_, &event, &error, &major, &minor);
  }
  void moveTo(QPoint global) {
    XTestFakeMotionEvent(display_, -1, global.x(), global.y(), 0 /* CurrentTime */);
    settle();
  }
  void button(unsigned int button, bool down) {
    XTestFakeButtonEvent(display_, button, down, 0);
    settle();
  }
  void click(unsigned int button) {
    this->button(button, true);
    this->button(button, false);
  }
  /// The key the symbol is on, at whatever level: XK_KP_Decimal is the keypad's ./Delete key,
  /// which gives KP_Delete with NumLock off.
  void key(KeySym symbol, bool down) {
    XTestFakeKeyEvent(display_, XKeysymToKeycode(display_, symbol), down, 0);
    settle();
  }
  bool numLock() {
    XkbStateRec state;
    XkbGetState(display_, XkbUseCoreKbd, &state);
    return state.locked_mods & XkbKeysymToModifiers(display_, XK_Num_Lock);
  }
  /// Presses NumLock until it is on (or off), as a user would.
  bool setNumLock(bool on) {
    for (int tries = 0; tries < 2 && numLock() != on; ++tries)
      press({XK_Num_Lock});
    return numLock() == on;
  }
  /// The keys pressed in order and released in reverse: a chord such as Shift+D.
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

/// A left-button drag from `from` to `to` (global pixels) in steps, sent from a thread of its
/// own while this one runs the event loop: a drag and drop (QDrag::exec) runs a loop of its own
/// inside the move that starts it, so events sent from here would wait for its end. Returns once
/// the button is up and the events are handled (at most timeoutMs).
inline bool dragWithEventsRunning(QPoint from, QPoint to, int steps = 12, int timeoutMs = 10000) {
  std::atomic<bool> done{false};
  std::thread sender([&] {
    Display* display = XOpenDisplay(nullptr);
    if (display) {
      const auto pause = [](int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); };
      const auto move = [&](QPoint p) {
        XTestFakeMotionEvent(display, -1, p.x(), p.y(), 0);
        XFlush(display);
        pause(40);
      };
      move(from);
      XTestFakeButtonEvent(display, 1, 1, 0);
      XFlush(display);
      pause(60);
      for (int k = 1; k <= steps; ++k)
        move(from + (to - from) * k / steps);
      pause(150);
      XTestFakeButtonEvent(display, 1, 0, 0);
      XFlush(display);
      pause(60);
      XCloseDisplay(display);
    }
    done = true;
  });
  const bool finished = QTest::qWaitFor([&] { return done.load(); }, timeoutMs);
  sender.join();
  QTest::qWait(50);
  return finished;
}

/// Makes w the active window as a click on its title would: with no window manager under Xvfb
/// nothing else gives a new window the X input focus.
inline bool activate(QWidget& w) {
  w.activateWindow();
  w.raise();
  return QTest::qWaitForWindowActive(&w);
}

} // namespace octaclay::app::testing

#undef None // X11's macros, which would hide Qt's and the app's names
#undef Bool
#undef Status
#undef KeyPress
#undef KeyRelease
#undef FocusIn
#undef FocusOut
#undef Unsorted
