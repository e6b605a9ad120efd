// The transmitter protocols' frame decoders on arbitrary byte streams (the first byte picks the
// protocol): they never crash, keep their buffer bounded, and every frame they return carries
// channel values the protocol can encode. Valid frames after the garbage are always found.
#include "FuzzTarget.h"

#include "devices/RcProtocols.h"

using namespace prisca::devices;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const RcProtocol protocols[] = {RcProtocol::Crsf, RcProtocol::Sbus, RcProtocol::Multiprotocol};
    const RcProtocol protocol = protocols[data[0] % 3];
    RcFrameDecoder decoder(protocol);
    const QByteArray garbage(reinterpret_cast<const char*>(data + 1),
                             static_cast<qsizetype>(size - 1));
    // In pieces of varying length, as a serial port delivers them.
    std::size_t at = 0;
    for (std::size_t piece = 1; at < std::size_t(garbage.size()); piece = piece % 61 + 7) {
        const auto frames = decoder.push(garbage.mid(qsizetype(at), qsizetype(piece)));
        for (const ChannelValues& values : frames) {
            for (int v : values) {
                FUZZ_CHECK(v >= 0 && v <= 2047);  // 11 bits
            }
        }
        at += piece;
    }
    ChannelValues sent{};
    for (std::size_t c = 0; c < sent.size(); ++c) {
        sent[c] = 172 + int((c * 97) % 1600);
    }
    QByteArray frame = protocol == RcProtocol::Crsf   ? encodeCrsf(sent)
                       : protocol == RcProtocol::Sbus ? encodeSbus(sent)
                                                      : encodeMultiprotocol(sent, {});
    // Four copies: garbage may begin a false frame that takes up to 64 bytes to rule out.
    const auto frames = decoder.push(frame + frame + frame + frame);
    FUZZ_CHECK(!frames.empty());
    FUZZ_CHECK(frames.back() == sent);
    return 0;
}
