#pragma once
// One fuzz target: libFuzzer calls LLVMFuzzerTestOneInput with each input (make fuzz); the
// replay driver (FuzzReplay.cpp) calls it with every file of the target's corpus in make test.
// A target returns 0; a broken property aborts (FUZZ_CHECK), which both drivers report.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

#define FUZZ_CHECK(condition)                                                                     \
    do {                                                                                          \
        if (!(condition)) {                                                                       \
            std::fprintf(stderr, "%s:%d: property broken: %s\n", __FILE__, __LINE__, #condition); \
            std::abort();                                                                         \
        }                                                                                         \
    } while (false)
