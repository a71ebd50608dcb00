// libFuzzer harness for the project reader and the evaluation of the tracks it accepts.
#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    gyre::fuzz::fuzzOneInput(gyre::fuzz::Reader::Project, "input.gyre", data, size);
    return 0;
}
