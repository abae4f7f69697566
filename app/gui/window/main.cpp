// octaclay: the modeller. `octaclay [doc.exr]` opens a document, or a new sphere (N = 1024).
#include "main_window.h"
#include "model_screenshot.h"
#include "screenshot_script.h"
#include "stretch_screenshot.h"
#include "viewport_widget.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QTimer>

#include <cstdio>

int main(int argc, char** argv) {
  QElapsedTimer sinceStart;
  sinceStart.start();
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName("Octaclay");
  QCoreApplication::setApplicationName("octaclay");
  QCoreApplication::setApplicationVersion("0.1.0");

  QCommandLineParser parser;
  parser.setApplicationDescription("Octaclay: sculpt closed surfaces stored as geometry images.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("document", "An Octaclay document (.exr) to open.", "[document]");
  QCommandLineOption shape("shape", "Shape of a new model: sphere, cube, cylinder, blob, capsule.",
                           "shape", "sphere");
  QCommandLineOption size("size", "Size N of a new model (N+1 samples a side).", "N", "1024");
  QCommandLineOption screenshot(
      "screenshot", "Make a few strokes, save the window as an image and quit.", "image.png");
  QCommandLineOption stretchScreenshot(
      "stretch-screenshot",
      "Show the document (a pulled limb) with Preview > Stretch before and after Mesh > Even Out "
      "Samples, save both side by side as an image and quit.",
      "image.png");
  QCommandLineOption remeshScreenshot(
      "remesh-screenshot",
      "Show the document (a creature) with Preview > Stretch before and after Mesh > Remesh, save "
      "both side by side as an image and quit.",
      "image.png");
  QCommandLineOption startupTime("startup-time",
                                 "Print the time from start to the first drawn frame, then quit.");
  QCommandLineOption modelScreenshot(
      "model-screenshot",
      "Show the document in the clay matcap from the front right with the snake-hook brush "
      "chosen, save the window as an image and quit.",
      "image.png");
  parser.addOptions(
      {shape, size, screenshot, stretchScreenshot, remeshScreenshot, startupTime, modelScreenshot});
  parser.process(app);

  const auto baseShape = octaclay::core::parseBaseShape(parser.value(shape).toStdString());
  bool sizeOk = false;
  const int n = parser.value(size).toInt(&sizeOk);
  if (!baseShape || !sizeOk || n < 2 || n > 8192 || (n & (n - 1)) != 0) {
    fprintf(stderr,
            "octaclay: --shape must be sphere, cube, cylinder, blob or capsule and --size a power "
            "of two from 2 to 8192\n");
    return 2;
  }

  const QStringList args = parser.positionalArguments();
  if (parser.isSet(modelScreenshot) && args.isEmpty()) {
    fprintf(stderr, "octaclay: --model-screenshot needs a document (see "
                    "scripts/creature-screenshot)\n");
    return 2;
  }
  if (parser.isSet(stretchScreenshot) && args.isEmpty()) {
    fprintf(stderr, "octaclay: --stretch-screenshot needs a document (a pulled limb, see "
                    "scripts/stretch-screenshot)\n");
    return 2;
  }

  if (parser.isSet(remeshScreenshot) && args.isEmpty()) {
    fprintf(stderr, "octaclay: --remesh-screenshot needs a document (a creature, see "
                    "scripts/remesh-screenshot)\n");
    return 2;
  }

  octaclay::app::MainWindow window;
  window.show();
  if (args.isEmpty() || !window.openDocument(args.front())) window.newDocument(*baseShape, n, true);
  if (parser.isSet(startupTime)) {
    QObject::connect(
        window.viewport(), &octaclay::app::ViewportWidget::framePainted, &app, [&sinceStart] {
          std::printf("first frame after %lld ms\n", static_cast<long long>(sinceStart.elapsed()));
          QCoreApplication::exit(0);
        });
  } else if (parser.isSet(screenshot)) {
    const QString out = parser.value(screenshot);
    QTimer::singleShot(0, &window, [&window, out] {
      const bool ok = octaclay::app::makeScreenshot(window, out);
      QCoreApplication::exit(ok ? 0 : 1);
    });
  } else if (parser.isSet(stretchScreenshot)) {
    const QString out = parser.value(stretchScreenshot);
    QTimer::singleShot(0, &window, [&window, out] {
      const bool ok = octaclay::app::makeStretchScreenshot(window, out);
      QCoreApplication::exit(ok ? 0 : 1);
    });
  } else if (parser.isSet(remeshScreenshot)) {
    const QString out = parser.value(remeshScreenshot);
    QTimer::singleShot(0, &window, [&window, out] {
      const bool ok = octaclay::app::makeStretchScreenshot(window, out,
                                                           octaclay::app::StretchOperation::Remesh);
      QCoreApplication::exit(ok ? 0 : 1);
    });
  } else if (parser.isSet(modelScreenshot)) {
    const QString out = parser.value(modelScreenshot);
    QTimer::singleShot(0, &window, [&window, out] {
      const bool ok = octaclay::app::makeModelScreenshot(window, "snake-hook", out);
      QCoreApplication::exit(ok ? 0 : 1);
    });
  } else {
    QTimer::singleShot(0, &window, [&window] { window.startSession(); });
  }
  return app.exec();
}
