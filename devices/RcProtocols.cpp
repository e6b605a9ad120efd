#include "devices/RcProtocols.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace prisca::devices {

namespace {
constexpr std::uint8_t kCrsfAddress = 0xC8;
constexpr std::uint8_t kCrsfRcChannels = 0x16;
constexpr int kCrsfFrameSize = 26;
constexpr std::uint8_t kSbusHeader = 0x0F;
constexpr int kSbusFrameSize = 25;
constexpr int kMultiFrameSize = 26;
}  // namespace

QString protocolName(RcProtocol protocol) {
    switch (protocol) {
        case RcProtocol::Crsf:
            return QStringLiteral("crsf");
        case RcProtocol::Sbus:
            return QStringLiteral("sbus");
        case RcProtocol::Multiprotocol:
            return QStringLiteral("multiprotocol");
        case RcProtocol::PpmBridge:
            return QStringLiteral("ppm-bridge");
    }
    return {};
}

std::optional<RcProtocol> parseProtocol(const QString& name) {
    for (RcProtocol p :
         {RcProtocol::Crsf, RcProtocol::Sbus, RcProtocol::Multiprotocol, RcProtocol::PpmBridge}) {
        if (name.compare(protocolName(p), Qt::CaseInsensitive) == 0) {
            return p;
        }
    }
    return std::nullopt;
}

SerialFormat defaultSerialFormat(RcProtocol protocol) {
    switch (protocol) {
        case RcProtocol::Crsf:
            return {420000, false, false};  // the handset-to-module rate ExpressLRS modules use
        case RcProtocol::Sbus:
        case RcProtocol::Multiprotocol:
        case RcProtocol::PpmBridge:
            return {100000, true, true};  // 100000 baud 8E2
    }
    return {};
}

int frameBytes(RcProtocol protocol) {
    switch (protocol) {
        case RcProtocol::Crsf:
        case RcProtocol::Multiprotocol:
            return 26;
        case RcProtocol::Sbus:
        case RcProtocol::PpmBridge:
            return 25;
    }
    return 26;
}

double lineFrameCapacity(RcProtocol protocol, int baud) {
    const SerialFormat format = defaultSerialFormat(protocol);
    const int bitsPerByte = 1 + 8 + (format.evenParity ? 1 : 0) + (format.twoStopBits ? 2 : 1);
    const int rate = baud > 0 ? baud : format.baud;
    return static_cast<double>(rate) / (bitsPerByte * frameBytes(protocol));
}

double maxFrameRate(RcProtocol protocol, int baud) {
    const double capacity = lineFrameCapacity(protocol, baud);
    if (sbusFraming(protocol)) {
        // SBUS has no length or checksum: receivers (and the bridge) find a frame by the quiet
        // line before it, so each frame is followed by a gap of kSbusGap at least.
        return 1.0 / (1.0 / capacity + kSbusGapSeconds);
    }
    return 0.8 * capacity;
}

std::uint8_t crc8DvbS2(const std::uint8_t* data, std::size_t size) {
    std::uint8_t crc = 0;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc & 0x80) ? static_cast<std::uint8_t>((crc << 1) ^ 0xD5)
                               : static_cast<std::uint8_t>(crc << 1);
        }
    }
    return crc;
}

std::uint16_t pulseToValue(RcProtocol protocol, double microseconds) {
    const double low = protocol == RcProtocol::Multiprotocol ? 204.0 : 172.0;
    const double high = protocol == RcProtocol::Multiprotocol ? 1843.0 : 1811.0;
    if (!std::isfinite(microseconds)) {
        microseconds = 1500.0;  // a non-number never leaves as a command: centre
    }
    const double v = low + (microseconds - 988.0) * (high - low) / 1024.0;
    return static_cast<std::uint16_t>(std::clamp(std::round(v), 0.0, 2047.0));
}

double valueToPulse(RcProtocol protocol, std::uint16_t value) {
    const double low = protocol == RcProtocol::Multiprotocol ? 204.0 : 172.0;
    const double high = protocol == RcProtocol::Multiprotocol ? 1843.0 : 1811.0;
    return 988.0 + (value - low) * 1024.0 / (high - low);
}

std::array<std::uint8_t, 22> packChannels(const ChannelValues& values) {
    std::array<std::uint8_t, 22> out{};
    int bit = 0;
    for (std::uint16_t v : values) {
        v &= 0x7FF;
        for (int b = 0; b < 11; ++b, ++bit) {
            if (v & (1u << b)) {
                out[bit / 8] |= static_cast<std::uint8_t>(1u << (bit % 8));
            }
        }
    }
    return out;
}

ChannelValues unpackChannels(const std::uint8_t* packed) {
    ChannelValues values{};
    int bit = 0;
    for (std::uint16_t& v : values) {
        v = 0;
        for (int b = 0; b < 11; ++b, ++bit) {
            if (packed[bit / 8] & (1u << (bit % 8))) {
                v |= static_cast<std::uint16_t>(1u << b);
            }
        }
    }
    return values;
}

QByteArray encodeCrsf(const ChannelValues& values) {
    QByteArray frame(kCrsfFrameSize, '\0');
    auto* b = reinterpret_cast<std::uint8_t*>(frame.data());
    b[0] = kCrsfAddress;
    b[1] = 24;  // type + 22 payload bytes + CRC
    b[2] = kCrsfRcChannels;
    const auto packed = packChannels(values);
    std::copy(packed.begin(), packed.end(), b + 3);
    b[25] = crc8DvbS2(b + 2, 23);
    return frame;
}

QByteArray encodeSbus(const ChannelValues& values, bool failsafe, bool channel17, bool channel18) {
    QByteArray frame(kSbusFrameSize, '\0');
    auto* b = reinterpret_cast<std::uint8_t*>(frame.data());
    b[0] = kSbusHeader;
    const auto packed = packChannels(values);
    std::copy(packed.begin(), packed.end(), b + 1);
    // Frame lost and failsafe together, as receivers send it.
    b[23] = static_cast<std::uint8_t>((failsafe ? 0x0C : 0x00) | (channel17 ? 0x01 : 0x00) |
                                      (channel18 ? 0x02 : 0x00));
    b[24] = 0x00;
    return frame;
}

QByteArray encodeMultiprotocol(const ChannelValues& values, const MultiprotocolHeader& h) {
    QByteArray frame(kMultiFrameSize, '\0');
    auto* b = reinterpret_cast<std::uint8_t*>(frame.data());
    const int protocol = std::clamp(h.protocol, 0, 63);
    b[0] = protocol < 32 ? 0x55 : 0x54;
    b[1] = static_cast<std::uint8_t>((protocol & 0x1F) | (h.bind ? 0x80 : 0) |
                                     (h.autoBind ? 0x40 : 0) | (h.rangeCheck ? 0x20 : 0));
    b[2] = static_cast<std::uint8_t>((std::clamp(h.receiverNumber, 0, 15)) |
                                     (std::clamp(h.subType, 0, 7) << 4) | (h.lowPower ? 0x80 : 0));
    b[3] = static_cast<std::uint8_t>(static_cast<std::int8_t>(std::clamp(h.option, -128, 127)));
    const auto packed = packChannels(values);
    std::copy(packed.begin(), packed.end(), b + 4);
    return frame;
}

std::vector<ChannelValues> RcFrameDecoder::push(const QByteArray& bytes) {
    buffer_ += bytes;
    std::vector<ChannelValues> frames;
    const auto u = [this](int i) { return static_cast<std::uint8_t>(buffer_[i]); };
    int start = 0;
    while (true) {
        const int available = static_cast<int>(buffer_.size()) - start;
        if (protocol_ == RcProtocol::Crsf) {
            if (available < 2) {
                break;
            }
            if (u(start) != kCrsfAddress && u(start) != 0xEE && u(start) != 0xEA) {
                ++start;
                ++skipped_;
                continue;
            }
            const int length = u(start + 1);
            if (length < 2 || length > 62) {
                ++start;
                ++skipped_;
                continue;
            }
            if (available < length + 2) {
                break;
            }
            const auto* frame = reinterpret_cast<const std::uint8_t*>(buffer_.constData()) + start;
            if (crc8DvbS2(frame + 2, length - 1) != frame[length + 1]) {
                ++start;  // not a frame after all: resynchronise one byte on
                ++skipped_;
                continue;
            }
            if (frame[2] == kCrsfRcChannels && length == 24) {
                frames.push_back(unpackChannels(frame + 3));
            }
            start += length + 2;
        } else {
            const int size = sbusFraming(protocol_) ? kSbusFrameSize : kMultiFrameSize;
            if (available < size) {
                break;
            }
            const auto* frame = reinterpret_cast<const std::uint8_t*>(buffer_.constData()) + start;
            const bool ok = sbusFraming(protocol_) ? frame[0] == kSbusHeader && frame[24] == 0x00
                                                   : (frame[0] == 0x55 || frame[0] == 0x54);
            if (!ok) {
                locked_ = false;
                ++start;
                ++skipped_;
                continue;
            }
            // SBUS and Multiprotocol carry no checksum: a header byte in garbage (or in a frame's
            // channel bytes) would start a false frame and hide the real ones after it. So the
            // first frame is taken only when the next one starts right after it; from then on
            // the stream is in step and every frame is taken as it comes.
            if (!locked_) {
                if (available < size + 1) {
                    break;  // wait for the next frame's first byte
                }
                const std::uint8_t next = frame[size];
                const bool nextOk =
                    sbusFraming(protocol_) ? next == kSbusHeader : (next == 0x55 || next == 0x54);
                if (!nextOk) {
                    ++start;
                    ++skipped_;
                    continue;
                }
                locked_ = true;
            }
            if (sbusFraming(protocol_)) {
                lastFailsafe_ = (frame[23] & 0x08) != 0;
                frames.push_back(unpackChannels(frame + 1));
            } else {
                frames.push_back(unpackChannels(frame + 4));
            }
            start += size;
        }
    }
    buffer_.remove(0, start);
    if (buffer_.size() > 4096) {  // a flood of garbage never grows the buffer without bound
        skipped_ += buffer_.size() - 64;
        buffer_ = buffer_.right(64);
    }
    return frames;
}

}  // namespace prisca::devices
