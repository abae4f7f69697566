// The acceptance tests that read the shared meshes (OCTACLAY_SHARED_DATA) skip when a mesh is
// missing, except under OCTACLAY_REQUIRE_SHARED_DATA (the ci preset), where a run without the
// data must not pass as green: there a missing mesh fails the test.
#pragma once

#include <QString>
#include <QTest>

#if OCTACLAY_REQUIRE_SHARED_DATA
#define OCTACLAY_MISSING_SHARED_DATA(name)                                                         \
  QFAIL(qPrintable(QStringLiteral("shared mesh %1 not found in OCTACLAY_SHARED_DATA (%2), which "  \
                                  "OCTACLAY_REQUIRE_SHARED_DATA (the ci preset) requires; point "  \
                                  "OCTACLAY_SHARED_DATA at the folder holding meshes/")            \
                       .arg(name, QStringLiteral(OCTACLAY_SHARED_DATA))))
#else
#define OCTACLAY_MISSING_SHARED_DATA(name) QSKIP("shared mesh not available")
#endif
