// libFuzzer target: the .finbook reader (strict and "open anyway") and the frame renderer.
//
// Invariants checked for every input, besides "no crash, no leak, no sanitizer report":
// whatever loads saves and loads again; whatever "open anyway" gives back is a valid document.
// Rendering covers paintFrame's clipping and paintList's folding at the canvas scale, capped
// at 512 pixels a side so one input stays cheap (the export of a huge canvas is banded and
// measured in app/tst_limits). Run with -rss_limit_mb and -timeout so cost bombs are findings.
#include "fuzz_checks.h"

#include <QCoreApplication>

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    static QCoreApplication app(*argc, *argv); // tr() and QImage want one
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_checks::readEveryWay(
        QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size)));
    return 0;
}
