// Raster image I/O (image_io.h): PNG read and written through libpng in every layout a file may
// have (grey, grey and alpha, RGB, RGBA, a palette, 16 bits), other formats through OpenCV, and
// damaged or absurd files refused with the file named, before memory is sized from them.

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"

#include <QColor>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

// The colour of pixel (x, y) of the test pictures: distinct in every channel.
QColor colourAt(int x, int y) {
  return QColor(40 * x + 10, 60 * y + 20, 255 - 30 * x - 20 * y, 100 + 25 * x + 10 * y);
}

constexpr int kWidth = 5, kHeight = 3;

QImage picture(QImage::Format format) {
  QImage image(kWidth, kHeight, QImage::Format_ARGB32);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      image.setPixelColor(x, y, colourAt(x, y));
  return image.convertToFormat(format);
}

void writeBytes(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

std::vector<std::uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void appendChunk(std::vector<std::uint8_t>& out, const char* type,
                 const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> chunk(type, type + 4);
  chunk.insert(chunk.end(), data.begin(), data.end());
  appendBigEndian(out, static_cast<std::uint32_t>(data.size()));
  out.insert(out.end(), chunk.begin(), chunk.end());
  appendBigEndian(
      out, static_cast<std::uint32_t>(crc32(0, chunk.data(), static_cast<uInt>(chunk.size()))));
}

// A PNG signature, a well-formed IHDR claiming width × height RGB pixels and a first IDAT of
// two bytes: what a reader sees before it sizes the pixels.
std::vector<std::uint8_t> headerOnlyPng(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> bytes{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  appendBigEndian(header, width);
  appendBigEndian(header, height);
  header.insert(header.end(), {8, 2, 0, 0, 0}); // 8 bits, RGB, deflate, no filter, no interlace
  appendChunk(bytes, "IHDR", header);
  appendChunk(bytes, "IDAT", {0x78, 0x9c});
  return bytes;
}

} // namespace

class ImageIoTest : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  fs::path at(const char* name) const { return fs::path(dir_.path().toStdString()) / name; }

private slots:
  // What writePng writes, readImage reads back: every channel of every pixel within rounding.
  void roundTripsEveryLayout() {
    for (int channels : {1, 3, 4}) {
      RasterImage image;
      image.width = kWidth;
      image.height = kHeight;
      image.channels = channels;
      for (int i = 0; i < kWidth * kHeight * channels; ++i)
        image.pixels.push_back(static_cast<float>((37 * i) % 256) / 255.0f);
      const fs::path file = at("round.png");
      writePng(image, file);
      const RasterImage back = readImage(file, channels);
      QCOMPARE(back.width, kWidth);
      QCOMPARE(back.height, kHeight);
      QCOMPARE(back.channels, channels);
      for (std::size_t i = 0; i < image.pixels.size(); ++i)
        QVERIFY2(std::abs(back.pixels[i] - image.pixels[i]) < 0.5f / 255,
                 qPrintable(QStringLiteral("channels %1, sample %2").arg(channels).arg(i)));
    }
  }

  // Files written by another program (Qt) in each layout a PNG may have: the colours read as
  // they were drawn, rows from the top, grey replicated, a missing alpha 1, colour to grey with
  // Rec. 601's weights. (Qt keeps the alpha in the palette's transparency chunk.)
  void readsEveryLayoutOfOtherWriters() {
    struct Case {
      const char* name;
      QImage::Format format;
      bool colour, alpha;
    } cases[] = {{"rgba.png", QImage::Format_ARGB32, true, true},
                 {"rgb.png", QImage::Format_RGB888, true, false},
                 {"grey.png", QImage::Format_Grayscale8, false, false},
                 {"grey16.png", QImage::Format_Grayscale16, false, false},
                 {"rgba64.png", QImage::Format_RGBA64, true, true},
                 {"palette.png", QImage::Format_Indexed8, true, true}};
    for (const Case& c : cases) {
      const QImage source = picture(c.format);
      const fs::path file = at(c.name);
      QVERIFY(source.save(QString::fromStdString(file.string()), "PNG"));
      const RasterImage rgba = readImage(file, 4);
      const RasterImage grey = readImage(file, 1);
      QCOMPARE(rgba.width, kWidth);
      QCOMPARE(rgba.height, kHeight);
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
          const QColor want = source.pixelColor(x, y);
          const float r = rgba.at(x, y, 0), g = rgba.at(x, y, 1), b = rgba.at(x, y, 2);
          const QString where = QStringLiteral("%1 at (%2, %3)").arg(c.name).arg(x).arg(y);
          QVERIFY2(std::abs(r - want.redF()) <= 1.0f / 255 &&
                       std::abs(g - want.greenF()) <= 1.0f / 255 &&
                       std::abs(b - want.blueF()) <= 1.0f / 255,
                   qPrintable(where));
          QVERIFY2(std::abs(rgba.at(x, y, 3) - (c.alpha ? want.alphaF() : 1.0f)) <= 1.0f / 255,
                   qPrintable(where));
          const float wantGrey = c.colour ? 0.299f * r + 0.587f * g + 0.114f * b : r;
          QVERIFY2(std::abs(grey.at(x, y, 0) - wantGrey) < 1e-5f, qPrintable(where));
        }
    }
  }

  // A format other than PNG still reads (a mesh's JPEG texture), through OpenCV.
  void readsJpegThroughOpenCv() {
    QImage flat(16, 16, QImage::Format_RGB888);
    flat.fill(QColor(200, 80, 40));
    const fs::path file = at("flat.jpg");
    QVERIFY(flat.save(QString::fromStdString(file.string()), "JPG", 95));
    const RasterImage image = readImage(file, 3);
    QCOMPARE(image.width, 16);
    QVERIFY(std::abs(image.at(8, 8, 0) - 200.0f / 255) < 4.0f / 255);
    QVERIFY(std::abs(image.at(8, 8, 1) - 80.0f / 255) < 4.0f / 255);
    QVERIFY(std::abs(image.at(8, 8, 2) - 40.0f / 255) < 4.0f / 255);
  }

  // Damaged, truncated, absurd or foreign files: Error(InvalidInput) naming the file; a header
  // claiming 100000² pixels is refused before its pixels are allocated.
  void refusesBadFiles() {
    const auto refused = [this](const char* name, const std::vector<std::uint8_t>& bytes,
                                const char* why) {
      const fs::path file = at(name);
      writeBytes(file, bytes);
      try {
        readImage(file, 3);
      } catch (const Error& e) {
        QCOMPARE(e.kind(), ErrorKind::InvalidInput);
        QVERIFY2(std::string(e.what()).find(file.string()) != std::string::npos, e.what());
        QVERIFY2(std::string(e.what()).find(why) != std::string::npos, e.what());
        return;
      }
      QFAIL(name);
    };
    writePng(RasterImage{4, 4, 3, std::vector<float>(48, 0.5f)}, at("good.png"));
    std::vector<std::uint8_t> truncated = readBytes(at("good.png"));
    truncated.resize(truncated.size() / 2);
    refused("truncated.png", truncated, "PNG");
    refused("huge.png", headerOnlyPng(100000, 100000), "larger than Octaclay reads");
    refused("text.png", {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'},
            "not an image");
    try {
      readImage(at("missing.png"), 3);
      QFAIL("a missing file was read");
    } catch (const Error& e) {
      QCOMPARE(e.kind(), ErrorKind::Io);
    }
  }
};

QTEST_GUILESS_MAIN(ImageIoTest)
#include "image_io_test.moc"
