#pragma once

#include <QByteArray>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>

namespace prisca::devices {

/// The serial protocols a transmitter link can speak.
enum class RcProtocol {
    Crsf,           ///< CRSF RC_CHANNELS_PACKED (ExpressLRS / Crossfire TX modules)
    Sbus,           ///< Futaba SBUS (25-byte frame)
    Multiprotocol,  ///< the DIY Multiprotocol TX module's serial protocol (26-byte frame)
    /// The trainer-port bridge (devices/firmware): SBUS frames on the wire, not inverted, which
    /// the bridge turns into 8-channel PPM for a transmitter's trainer port.
    PpmBridge,
};

/// Whether a protocol's frames are SBUS's (SBUS itself and the PPM bridge).
inline bool sbusFraming(RcProtocol protocol) {
    return protocol == RcProtocol::Sbus || protocol == RcProtocol::PpmBridge;
}

/// "crsf", "sbus", "multiprotocol", "ppm-bridge" (command-line and settings names).
QString protocolName(RcProtocol protocol);
std::optional<RcProtocol> parseProtocol(const QString& name);

/// Serial settings of a protocol: baud rate, 8 data bits, parity and stop bits.
struct SerialFormat {
    int baud = 0;
    bool evenParity = false;
    bool twoStopBits = false;
};
SerialFormat defaultSerialFormat(RcProtocol protocol);

/// Bytes in one frame: CRSF 26, SBUS and the PPM bridge 25, Multiprotocol 26.
int frameBytes(RcProtocol protocol);
/// Frames per second the line carries at a baud rate (0: the protocol's), each byte a start bit,
/// 8 data bits, the parity bit if any and the stop bits: SBUS at 100000 baud 8E2 about 333.
double lineFrameCapacity(RcProtocol protocol, int baud);
/// The quiet line an SBUS frame is followed by at least [s]: the bridge's firmware takes 2 ms
/// of silence (two of its 1.024 ms ticks at most) as a frame boundary; a third more for jitter.
constexpr double kSbusGapSeconds = 0.003;
/// The most frames per second a link may send, so that frames never queue on the wire (a
/// failsafe then goes out next, not behind a queue of driving frames): four fifths of the line's
/// capacity; for SBUS framing each frame and its gap (SBUS at 100000 baud: 166).
double maxFrameRate(RcProtocol protocol, int baud);

/// 16 channels as pulse widths [us] (988 = -100 %, 1500 = centre, 2012 = +100 %).
using ChannelPulses = std::array<double, 16>;
/// 16 channels as the protocol's 11-bit values.
using ChannelValues = std::array<std::uint16_t, 16>;

/// CRC-8 with polynomial 0xD5 (CRC-8/DVB-S2: init 0, no reflection, no final xor), as CRSF uses.
std::uint8_t crc8DvbS2(const std::uint8_t* data, std::size_t size);

/// Pulse width [us] to the protocol's 11-bit value: CRSF and SBUS map 988..2012 us onto
/// 172..1811 (1500 us -> 992), Multiprotocol onto 204..1843 (-100 %..+100 %, 1500 us -> 1024);
/// values beyond are extrapolated and clamped to 0..2047.
std::uint16_t pulseToValue(RcProtocol protocol, double microseconds);
/// The inverse (for decoding in tests and the virtual rig).
double valueToPulse(RcProtocol protocol, std::uint16_t value);

/// Packs 16 x 11-bit values least significant bit first into 22 bytes (CRSF, SBUS and
/// Multiprotocol all pack this way).
std::array<std::uint8_t, 22> packChannels(const ChannelValues& values);
ChannelValues unpackChannels(const std::uint8_t* packed);

/// CRSF RC_CHANNELS_PACKED: 0xC8 (address of the flight controller / module), length 24,
/// type 0x16, 22 bytes of channels, CRC-8/DVB-S2 over type and payload. 26 bytes.
QByteArray encodeCrsf(const ChannelValues& values);
/// SBUS: 0x0F, 22 bytes of channels, flags (bit 0 digital channel 17, bit 1 digital channel 18,
/// bit 2 frame lost, bit 3 failsafe), 0x00. 25 bytes.
QByteArray encodeSbus(const ChannelValues& values, bool failsafe = false, bool channel17 = false,
                      bool channel18 = false);
/// Multiprotocol serial, 26 bytes: header 0x55 (sub-protocol 0..31) or 0x54 (32..63), then
/// sub-protocol | bind 0x80 | autobind 0x40 | range check 0x20, then rx number | type << 4 |
/// low power 0x80, then the option byte, then 22 bytes of channels.
struct MultiprotocolHeader {
    int protocol = 0;        ///< 0..63
    int subType = 0;         ///< 0..7
    int receiverNumber = 0;  ///< 0..15
    int option = 0;          ///< -128..127
    bool bind = false;
    bool autoBind = false;
    bool rangeCheck = false;
    bool lowPower = false;
};
QByteArray encodeMultiprotocol(const ChannelValues& values, const MultiprotocolHeader& header);

/// Finds protocol frames in a byte stream (the far end of a link in tests and the virtual rig).
/// Garbage between frames is skipped; a CRSF frame with a bad CRC is dropped; SBUS and
/// Multiprotocol frames (no checksum) are taken once two start back to back. Never throws.
class RcFrameDecoder {
  public:
    explicit RcFrameDecoder(RcProtocol protocol) : protocol_(protocol) {}
    /// Appends bytes; returns every complete frame's channel values found so far, in order.
    std::vector<ChannelValues> push(const QByteArray& bytes);
    /// Bytes skipped as not belonging to any frame.
    long long skippedBytes() const { return skipped_; }
    /// The failsafe flag of the last SBUS frame.
    bool lastFailsafe() const { return lastFailsafe_; }

  private:
    RcProtocol protocol_;
    QByteArray buffer_;
    long long skipped_ = 0;
    bool lastFailsafe_ = false;
    bool locked_ = false;  ///< SBUS, Multiprotocol: in step with the frames
};

}  // namespace prisca::devices
