// RC protocol encoders: CRC-8/DVB-S2's check value, the pulse mapping's anchors, bit packing,
// round trips, and frames against published ones; the decoder never crashes on garbage.
#include "devices/ChannelMap.h"
#include "devices/RcProtocols.h"

#include <QtTest>

#include <random>

using namespace prisca::devices;

class TestRcProtocols : public QObject {
    Q_OBJECT
  private slots:
    void crc8_dvbS2CheckValue() {
        // The catalogue check value of CRC-8/DVB-S2 over ASCII "123456789" (the CRC catalogue:
        // width=8 poly=0xd5 init=0x00 refin=false refout=false xorout=0x00 check=0xbc).
        const char* check = "123456789";
        QCOMPARE(crc8DvbS2(reinterpret_cast<const std::uint8_t*>(check), 9), std::uint8_t(0xBC));
    }

    void pulses_mapOntoTheProtocolsAnchors() {
        QCOMPARE(pulseToValue(RcProtocol::Crsf, 988), std::uint16_t(172));
        QCOMPARE(pulseToValue(RcProtocol::Crsf, 1500), std::uint16_t(992));
        QCOMPARE(pulseToValue(RcProtocol::Crsf, 2012), std::uint16_t(1811));
        QCOMPARE(pulseToValue(RcProtocol::Sbus, 1500), std::uint16_t(992));
        QCOMPARE(pulseToValue(RcProtocol::Multiprotocol, 988), std::uint16_t(204));
        QCOMPARE(pulseToValue(RcProtocol::Multiprotocol, 1500), std::uint16_t(1024));
        QCOMPARE(pulseToValue(RcProtocol::Multiprotocol, 2012), std::uint16_t(1843));
        // Never outside 11 bits, never undefined.
        QCOMPARE(pulseToValue(RcProtocol::Crsf, 1e9), std::uint16_t(2047));
        QCOMPARE(pulseToValue(RcProtocol::Crsf, -1e9), std::uint16_t(0));
        QCOMPARE(pulseToValue(RcProtocol::Crsf, std::nan("")), std::uint16_t(992));
    }

    void packing_isLeastSignificantBitFirstAndRoundTrips() {
        ChannelValues v{};
        v[0] = 0x7FF;  // all ones in the first 11 bits
        auto packed = packChannels(v);
        QCOMPARE(packed[0], std::uint8_t(0xFF));
        QCOMPARE(packed[1], std::uint8_t(0x07));
        QCOMPARE(packed[2], std::uint8_t(0x00));
        v = {};
        v[1] = 1;  // bit 11 of the stream
        packed = packChannels(v);
        QCOMPARE(packed[1], std::uint8_t(0x08));
        std::mt19937 random(5);
        for (int trial = 0; trial < 200; ++trial) {
            for (auto& x : v)
                x = static_cast<std::uint16_t>(random() & 0x7FF);
            QCOMPARE(unpackChannels(packChannels(v).data()), v);
        }
    }

    void crsf_matchesAPublishedFrameByteForByte() {
        // Source: github.com/rtlopez/esp-fc, test/test_input_crsf/test_input_crsf.cpp,
        // test_crsf_encode_rc: every channel 992 (centre) except CH3 = 172 (throttle low),
        // encoded to this frame (CRC 0xDB).
        const std::uint8_t published[26] = {0xC8, 0x18, 0x16, 0xE0, 0x03, 0x1F, 0x2B, 0xC0, 0x07,
                                            0x3E, 0xF0, 0x81, 0x0F, 0x7C, 0xE0, 0x03, 0x1F, 0xF8,
                                            0xC0, 0x07, 0x3E, 0xF0, 0x81, 0x0F, 0x7C, 0xDB};
        ChannelValues v;
        v.fill(992);
        v[2] = 172;
        const QByteArray frame = encodeCrsf(v);
        QCOMPARE(frame, QByteArray(reinterpret_cast<const char*>(published), 26));
        // And from pulse widths, as the link sends them: 1500 us centre, 988 us low.
        ChannelValues fromPulses;
        for (int c = 0; c < 16; ++c) {
            fromPulses[c] = pulseToValue(RcProtocol::Crsf, c == 2 ? 988.0 : 1500.0);
        }
        QCOMPARE(encodeCrsf(fromPulses), frame);
        RcFrameDecoder decoder(RcProtocol::Crsf);
        const auto decoded = decoder.push(frame);
        QCOMPARE(decoded.size(), size_t(1));
        QCOMPARE(decoded[0], v);
    }

    void crsf_matchesCapturedFramesByteForByte() {
        // Source: github.com/betaflight/betaflight, src/test/unit/rx_crsf_unittest.cc,
        // CrossFireTest.TestCapturedData: two captured RC frames (address 0x00, broadcast);
        // the test asserts CH1-4 = 189, 993, 978, 983 (then 981) and the CRC. The other
        // channels are these bytes decoded. The CRC does not cover the address, so only byte
        // 0 differs from our 0xC8.
        const std::uint8_t captured[2][26] = {
            {0x00, 0x18, 0x16, 0xBD, 0x08, 0x9F, 0xF4, 0xAE, 0xF7, 0xBD, 0xEF, 0x7D, 0xEF,
             0xFB, 0xAD, 0xFD, 0x45, 0x2B, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x6C},
            {0x00, 0x18, 0x16, 0xBD, 0x08, 0x9F, 0xF4, 0xAA, 0xF7, 0xBD, 0xEF, 0x7D, 0xEF,
             0xFB, 0xAD, 0xFD, 0x45, 0x2B, 0x5A, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x94}};
        const int fourth[2] = {983, 981};
        for (int f = 0; f < 2; ++f) {
            const ChannelValues v = unpackChannels(captured[f] + 3);
            QCOMPARE(v[0], std::uint16_t(189));
            QCOMPARE(v[1], std::uint16_t(993));
            QCOMPARE(v[2], std::uint16_t(978));
            QCOMPARE(v[3], std::uint16_t(fourth[f]));
            const QByteArray frame = encodeCrsf(v);
            QCOMPARE(frame.mid(1), QByteArray(reinterpret_cast<const char*>(captured[f]) + 1, 25));
        }
    }

    void sbus_matchesPublishedFramesByteForByte() {
        // Source: github.com/zklapow/sbus, tests/parse_tester.rs, test_sbus_parse_basic: this
        // frame is channels 992, 992, 352, 992, 352 x 6, 992, 992, 0 x 4 with both digital
        // channels (17, 18) on, neither failsafe nor frame lost.
        const std::uint8_t basic[25] = {0x0F, 0xE0, 0x03, 0x1F, 0x58, 0xC0, 0x07, 0x16, 0xB0,
                                        0x80, 0x05, 0x2C, 0x60, 0x01, 0x0B, 0xF8, 0xC0, 0x07,
                                        0x00, 0x00, 0x00, 0x00, 0x00, 0x03, 0x00};
        const ChannelValues channels = {992, 992, 352, 992, 352, 352, 352, 352,
                                        352, 352, 992, 992, 0,   0,   0,   0};
        QCOMPARE(encodeSbus(channels, false, true, true),
                 QByteArray(reinterpret_cast<const char*>(basic), 25));
        // Source: github.com/ArduPilot/ardupilot,
        // libraries/AP_RCProtocol/examples/RCProtocolTest/RCProtocolTest.cpp: this frame is
        // expected to read as 1562, 1496, 1000, 1531, 1806, 2006, 1495, 1495, 875 ... us with
        // ArduPilot's scale (raw x 0.625 + 875, truncated). Decoded raw values, re-encoded:
        const std::uint8_t ardupilot[25] = {0x0F, 0x4C, 0x1C, 0x5F, 0x32, 0x34, 0x38, 0xDD, 0x89,
                                            0x83, 0x0F, 0x7C, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                            0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
        const int microseconds[9] = {1562, 1496, 1000, 1531, 1806, 2006, 1495, 1495, 875};
        const ChannelValues raw = unpackChannels(ardupilot + 1);
        for (int c = 0; c < 9; ++c) {
            QCOMPARE(static_cast<int>(raw[c] * 0.625 + 875), microseconds[c]);
        }
        QCOMPARE(encodeSbus(raw), QByteArray(reinterpret_cast<const char*>(ardupilot), 25));
    }

    void multiprotocol_followsThePublishedLayout() {
        // No complete published frame exists; the layout is the module's own
        // (github.com/pascallanger/DIY-Multiprotocol-TX-Module, Multiprotocol/Multiprotocol.h,
        // "Serial: 100000 Baud 8e2 ... Total of 26 bytes"): channels packed "like in SBUS",
        // so bytes 4..25 are SBUS's bytes 1..22 for the same values.
        const ChannelValues channels = {992, 992, 352, 992, 352, 352, 352, 352,
                                        352, 352, 992, 992, 0,   0,   0,   0};
        const QByteArray multi = encodeMultiprotocol(channels, {});
        QCOMPARE(multi.mid(4, 22), encodeSbus(channels).mid(1, 22));
        // The one literal fragment published (Multiprotocol/Multiprotocol.ino, under SAMSON):
        // header 0x55, protocol FRSKYD (3) in byte 1, byte 2 = 0x7F (sub-type 7, receiver 15),
        // and CH15 = CH16 = 1622 (73 %) giving bytes 24, 25 = 217, 202.
        MultiprotocolHeader h;
        h.protocol = 3;
        h.subType = 7;
        h.receiverNumber = 15;
        ChannelValues v;
        v.fill(1024);
        v[14] = v[15] = 1622;
        const QByteArray frame = encodeMultiprotocol(v, h);
        QCOMPARE(std::uint8_t(frame[0]), std::uint8_t(0x55));
        QCOMPARE(std::uint8_t(frame[1]) & 0x1F, 3);
        QCOMPARE(std::uint8_t(frame[2]), std::uint8_t(0x7F));
        QCOMPARE(std::uint8_t(frame[24]), std::uint8_t(217));
        QCOMPARE(std::uint8_t(frame[25]), std::uint8_t(202));
        // The documented scale: -100 % = 204, 0 % = 1024, +100 % = 1843.
        QCOMPARE(pulseToValue(RcProtocol::Multiprotocol, 988.0), std::uint16_t(204));
        QCOMPARE(pulseToValue(RcProtocol::Multiprotocol, 2012.0), std::uint16_t(1843));
    }

    void frames_haveTheProtocolsShape() {
        ChannelValues v;
        v.fill(992);
        const QByteArray crsf = encodeCrsf(v);
        QCOMPARE(crsf.size(), 26);
        QCOMPARE(std::uint8_t(crsf[0]), std::uint8_t(0xC8));
        QCOMPARE(std::uint8_t(crsf[1]), std::uint8_t(24));
        QCOMPARE(std::uint8_t(crsf[2]), std::uint8_t(0x16));
        QCOMPARE(std::uint8_t(crsf[25]),
                 crc8DvbS2(reinterpret_cast<const std::uint8_t*>(crsf.constData()) + 2, 23));
        const QByteArray sbus = encodeSbus(v, true);
        QCOMPARE(sbus.size(), 25);
        QCOMPARE(std::uint8_t(sbus[0]), std::uint8_t(0x0F));
        QCOMPARE(std::uint8_t(sbus[23]), std::uint8_t(0x0C));
        QCOMPARE(std::uint8_t(sbus[24]), std::uint8_t(0x00));
        MultiprotocolHeader h;
        h.protocol = 33;  // > 31: header 0x54, low five bits in byte 1
        h.subType = 2;
        h.receiverNumber = 5;
        h.option = -3;
        h.bind = true;
        const QByteArray multi = encodeMultiprotocol(v, h);
        QCOMPARE(multi.size(), 26);
        QCOMPARE(std::uint8_t(multi[0]), std::uint8_t(0x54));
        QCOMPARE(std::uint8_t(multi[1]), std::uint8_t(0x80 | 1));
        QCOMPARE(std::uint8_t(multi[2]), std::uint8_t(5 | (2 << 4)));
        QCOMPARE(std::uint8_t(multi[3]), std::uint8_t(0xFD));
    }

    void decoder_findsFramesAmongGarbageAndNeverCrashes() {
        ChannelValues v{};
        for (int c = 0; c < 16; ++c)
            v[c] = static_cast<std::uint16_t>(172 + c * 100);
        for (RcProtocol p : {RcProtocol::Crsf, RcProtocol::Sbus, RcProtocol::Multiprotocol}) {
            const QByteArray frame = p == RcProtocol::Crsf   ? encodeCrsf(v)
                                     : p == RcProtocol::Sbus ? encodeSbus(v)
                                                             : encodeMultiprotocol(v, {});
            RcFrameDecoder decoder(p);
            QByteArray stream = QByteArray("\x01\x02\x03junk", 7) + frame + frame.left(10);
            auto frames = decoder.push(stream);
            QCOMPARE(frames.size(), size_t(1));
            QCOMPARE(frames[0], v);
            frames = decoder.push(frame.mid(10));  // the rest of the split frame
            QCOMPARE(frames.size(), size_t(1));
            QCOMPARE(frames[0], v);
            QVERIFY(decoder.skippedBytes() >= 7);
            // Random bytes: whatever comes out, nothing crashes and the buffer stays bounded.
            std::mt19937 random(11);
            for (int chunk = 0; chunk < 200; ++chunk) {
                QByteArray junk(512, '\0');
                for (char& b : junk)
                    b = static_cast<char>(random());
                decoder.push(junk);
            }
            frames = decoder.push(frame + frame);
            QVERIFY(!frames.empty());
            QCOMPARE(frames.back(), v);
        }
        // A CRSF frame with a wrong CRC is not taken.
        QByteArray bad = encodeCrsf(v);
        bad[25] = static_cast<char>(bad[25] ^ 0x01);
        RcFrameDecoder crsf(RcProtocol::Crsf);
        QVERIFY(crsf.push(bad).empty());
    }

    void channelMap_commandsFailsafeAndChecks() {
        ChannelMap map = ChannelMap::car();
        QVERIFY(map.validate().isEmpty());
        map.controls[1].trim = 20;
        map.controls[1].reversed = true;
        const ChannelPulses full = map.command(Eigen::Vector2d(1.0, 1.0));
        QCOMPARE(full[2], 2012.0);                 // throttle on CH3
        QCOMPARE(full[0], 1500.0 + 20.0 - 512.0);  // steering on CH1, reversed, trimmed
        QCOMPARE(full[5], 1500.0);                 // unmapped
        const ChannelPulses safe = map.failsafe();
        QCOMPARE(safe[2], 1500.0);  // throttle neutral
        QCOMPARE(safe[0], 1520.0);  // steering centred (with its trim)
        // A NaN control is neutral, never undefined.
        QCOMPARE(map.command(Eigen::Vector2d(std::nan(""), 0.0))[2], 1500.0);
        map.controls[1].channel = 2;
        QVERIFY(map.validate().contains("twice"));
        map = ChannelMap::car();
        map.controls[0].minimum = 2100;
        QVERIFY(!map.validate().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestRcProtocols)
#include "test_rc_protocols.moc"
