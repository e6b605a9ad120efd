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
        // The catalogue check value of CRC-8/DVB-S2 over ASCII "123456789".
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
