// Running octaclay-cli from tests: exit code, stdout and stderr, and macros that check them.
#pragma once

#include <QByteArray>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>
#include <QtTest>

namespace cli_support {

constexpr int kOk = 0, kUsage = 2, kInvalidInput = 3, kIo = 4, kGl = 5;

struct Result {
  int exitCode = -1;
  QByteArray out, err;
  bool crashed = false;
};

// Runs octaclay-cli with args; env entries (NAME=value) are added to its environment.
inline Result runCli(const QStringList& args, const QStringList& env = {}) {
  QProcess process;
  if (!env.isEmpty()) {
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    for (const QString& e : env)
      environment.insert(e.section('=', 0, 0), e.section('=', 1));
    process.setProcessEnvironment(environment);
  }
  process.start(QStringLiteral(OCTACLAY_CLI), args);
  Result r;
  if (!process.waitForStarted(10000)) {
    r.crashed = true;
    r.err = "could not start " OCTACLAY_CLI ": " + process.errorString().toUtf8();
    return r;
  }
  if (!process.waitForFinished(60000)) {
    process.kill();
    process.waitForFinished();
  }
  r.crashed = process.exitStatus() != QProcess::NormalExit;
  r.exitCode = process.exitCode();
  r.out = process.readAllStandardOutput();
  r.err = process.readAllStandardError();
  return r;
}

inline QString describe(const QStringList& args, const Result& r) {
  return QString("octaclay-cli %1 -> exit %2%3\nstdout: %4\nstderr: %5")
      .arg(args.join(' '))
      .arg(r.exitCode)
      .arg(r.crashed ? " (crashed)" : "")
      .arg(QString::fromUtf8(r.out.left(2000)), QString::fromUtf8(r.err.left(2000)));
}

} // namespace cli_support

using namespace cli_support;

// Runs the CLI expecting success and --json output parsed into a new QJsonObject `var`.
#define RUN_JSON(var, ...)                                                                         \
  QJsonObject var;                                                                                 \
  do {                                                                                             \
    const QStringList args_{__VA_ARGS__};                                                          \
    const Result r_ = runCli(args_);                                                               \
    QVERIFY2(!r_.crashed && r_.exitCode == kOk, qPrintable(describe(args_, r_)));                  \
    QJsonParseError error_{};                                                                      \
    const QJsonDocument doc_ = QJsonDocument::fromJson(r_.out, &error_);                           \
    QVERIFY2(error_.error == QJsonParseError::NoError && doc_.isObject(),                          \
             qPrintable("stdout is not one JSON object (" + error_.errorString() +                 \
                        "): " + describe(args_, r_)));                                             \
    var = doc_.object();                                                                           \
  } while (false)

// Runs the CLI expecting `code`, a message on stderr and no file at `output` (may be empty).
#define EXPECT_FAILURE(code, output, ...)                                                          \
  do {                                                                                             \
    const QStringList args_{__VA_ARGS__};                                                          \
    const Result r_ = runCli(args_);                                                               \
    QVERIFY2(!r_.crashed && r_.exitCode == (code), qPrintable(describe(args_, r_)));               \
    QVERIFY2(!r_.err.trimmed().isEmpty(), qPrintable("no message: " + describe(args_, r_)));       \
    if (!QString(output).isEmpty())                                                                \
      QVERIFY2(!QFileInfo::exists(output),                                                         \
               qPrintable("output left behind: " + describe(args_, r_)));                          \
  } while (false)
