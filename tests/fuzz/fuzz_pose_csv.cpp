// libFuzzer harness for the CSV readers: each input read as a pose file and as a number file.
#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    gyre::fuzz::fuzzOneInput(gyre::fuzz::Reader::PoseCsv, "input.csv", data, size);
    gyre::fuzz::fuzzOneInput(gyre::fuzz::Reader::NumberCsv, "input.csv", data, size);
    return 0;
}
