// The trainer-port bridge's firmware on a simulated ATmega328P at 16 MHz: the link's own SBUS
// frames (devices::encodeSbus, as the transmitter link writes them) go into its UART, the PPM
// on OC1A (PB1) is timed from the pin's edges in CPU cycles. Pulse widths within 2 us of the
// command, the frame period, the watchdog's neutral after silence, the failsafe frame at once,
// garbage ignored (a frame only between quiet gaps, two good ones in a row before output).
#include "devices/RcProtocols.h"

#include <QtTest>

#include "avr_ioport.h"
#include "avr_uart.h"
#include "sim_avr.h"
#include "sim_elf.h"

#include <cmath>
#include <cstdint>
#include <vector>

using namespace prisca::devices;

namespace {

constexpr double kHz = 16e6;

class Bridge {
  public:
    Bridge() {
        elf_firmware_t firmware{};
        if (elf_read_firmware(PPM_BRIDGE_ELF, &firmware) != 0) {
            qFatal("cannot read %s", PPM_BRIDGE_ELF);
        }
        avr_ = avr_make_mcu_by_name("atmega328p");
        avr_init(avr_);
        avr_->frequency = static_cast<uint32_t>(kHz);
        avr_->log = 0;
        avr_load_firmware(avr_, &firmware);
        avr_irq_register_notify(avr_io_getirq(avr_, AVR_IOCTL_IOPORT_GETIRQ('B'), 1), &Bridge::pin,
                                this);
        uart_ = avr_io_getirq(avr_, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    }
    ~Bridge() { avr_terminate(avr_); }

    double now() const { return avr_->cycle / kHz; }
    /// Runs the chip until `seconds` of its time. False if it crashed or stopped.
    bool runUntil(double seconds) {
        while (now() < seconds) {
            const int state = avr_run(avr_);
            if (state == cpu_Done || state == cpu_Crashed) {
                return false;
            }
            // Bytes queued go in one at a time, each once the last has had its 120 us on the
            // wire (12 bits at 100000 baud).
            if (!queue_.empty() && now() >= nextByte_) {
                avr_raise_irq(uart_, queue_.front());
                queue_.erase(queue_.begin());
                nextByte_ = now() + 120e-6;
                lastByteSent_ = now();
            }
        }
        return true;
    }
    void send(const QByteArray& bytes) {
        for (char c : bytes) {
            queue_.push_back(static_cast<uint8_t>(c));
        }
        nextByte_ = std::max(nextByte_, now());
    }
    /// When the last queued byte went in [s].
    double lastByteSent() const { return lastByteSent_; }

    /// The PPM frames seen: each its start (first rising edge) and its 8 channels [us] (rising
    /// edge to rising edge), split at the sync gap.
    struct Frame {
        double start = 0.0;
        std::vector<double> channelStarts;  ///< [s]
        std::vector<double> widths;         ///< [us]
    };
    std::vector<Frame> frames() const {
        std::vector<double> rises;
        for (const auto& [cycle, level] : edges_) {
            if (level == 1) {
                rises.push_back(cycle / kHz);
            }
        }
        std::vector<Frame> out;
        Frame f;
        for (size_t i = 0; i + 1 < rises.size(); ++i) {
            const double gap = rises[i + 1] - rises[i];
            if (f.widths.empty()) {
                f.start = rises[i];
            }
            if (gap > 0.003) {  // the sync gap: this rise ended channel 8
                if (f.widths.size() == 8) {
                    out.push_back(f);
                }
                f = Frame{};
                continue;
            }
            f.channelStarts.push_back(rises[i]);
            f.widths.push_back(gap * 1e6);
        }
        return out;
    }

  private:
    static void pin(avr_irq_t*, uint32_t value, void* self) {
        auto* b = static_cast<Bridge*>(self);
        const int level = static_cast<int>(value & 1);
        if (b->edges_.empty() || b->edges_.back().second != level) {
            b->edges_.emplace_back(b->avr_->cycle, level);
        }
    }

    avr_t* avr_ = nullptr;
    avr_irq_t* uart_ = nullptr;
    std::vector<std::pair<avr_cycle_count_t, int>> edges_;
    std::vector<uint8_t> queue_;
    double nextByte_ = 0.0, lastByteSent_ = 0.0;
};

QByteArray sbus(const std::vector<double>& microseconds, bool failsafe = false) {
    ChannelValues values{};
    for (int c = 0; c < 16; ++c) {
        values[c] =
            pulseToValue(RcProtocol::PpmBridge,
                         c < static_cast<int>(microseconds.size()) ? microseconds[c] : 1500.0);
    }
    return encodeSbus(values, failsafe);
}

bool within(const std::vector<double>& widths, const std::vector<double>& expected, double tol) {
    for (size_t c = 0; c < widths.size(); ++c) {
        if (std::abs(widths[c] - expected[c]) > tol) {
            return false;
        }
    }
    return true;
}

const std::vector<double> kNeutral(8, 1500.0);
const std::vector<double> kCommand = {1000, 1200, 1500, 1800, 2000, 1100, 1900, 1650};

}  // namespace

class TestPpmBridge : public QObject {
    Q_OBJECT
  private slots:
    void bridge_sendsTheCommandedPulsesAndGoesNeutralOnSilence() {
        Bridge bridge;
        QVERIFY(bridge.runUntil(0.1));
        // Before any frame: neutral, at 22.5 ms a frame.
        auto frames = bridge.frames();
        QVERIFY(frames.size() >= 3);
        for (const auto& f : frames) {
            QVERIFY(within(f.widths, kNeutral, 2.0));
        }
        for (size_t i = 1; i < frames.size(); ++i) {
            QVERIFY(std::abs((frames[i].start - frames[i - 1].start) * 1e6 - 22500.0) < 2.0);
        }
        // The link's frames every 10 ms for half a second.
        double t = 0.1;
        for (; t < 0.6; t += 0.010) {
            bridge.send(sbus(kCommand));
            QVERIFY(bridge.runUntil(t + 0.010));
        }
        const double silentFrom = bridge.lastByteSent();
        QVERIFY(bridge.runUntil(silentFrom + 0.4));
        frames = bridge.frames();
        int commanded = 0;
        double worst = 0.0;
        double firstNeutral = -1.0;
        for (const auto& f : frames) {
            if (f.start > 0.13 && f.start < silentFrom) {  // whole frames after the first command
                for (size_t c = 0; c < 8; ++c) {
                    worst = std::max(worst, std::abs(f.widths[c] - kCommand[c]));
                }
                ++commanded;
            }
            if (f.start > silentFrom && f.start < silentFrom + 0.200) {
                QVERIFY2(within(f.widths, kCommand, 2.0), "neutral before 200 ms of silence");
            }
            if (firstNeutral < 0 && f.start > silentFrom && within(f.widths, kNeutral, 2.0)) {
                firstNeutral = f.start;
            }
        }
        for (size_t i = 1; i < frames.size(); ++i) {
            QVERIFY(std::abs((frames[i].start - frames[i - 1].start) * 1e6 - 22500.0) < 2.0);
        }
        qInfo(
            "%d commanded frames, worst pulse error %.2f us; neutral %.1f ms after the last "
            "byte",
            commanded, worst, (firstNeutral - silentFrom) * 1e3);
        QVERIFY(commanded >= 18);
        QVERIFY(worst <= 2.0);
        QVERIFY(firstNeutral > 0 && firstNeutral - silentFrom <= 0.250);
    }

    void bridge_honoursAFailsafeFrameAtOnce() {
        Bridge bridge;
        double t = 0.0;
        for (; t < 0.2; t += 0.010) {
            bridge.send(sbus({1900, 1900, 1900, 1900, 1900, 1900, 1900, 1900}));
            QVERIFY(bridge.runUntil(t + 0.010));
        }
        // The failsafe frame lands in the middle of a PPM frame.
        const auto before = bridge.frames();
        QVERIFY(!before.empty());
        QVERIFY(bridge.runUntil(before.back().start + 22.5e-3 + 0.004));
        bridge.send(sbus(kNeutral, true));
        QVERIFY(bridge.runUntil(bridge.now() + 0.004));
        // Taken once the line has been quiet for its closing gap (2.05 ms at most after the
        // last byte's 120 us).
        const double received = bridge.lastByteSent() + 120e-6 + 2.05e-3;
        QVERIFY(bridge.runUntil(received + 0.1));
        int after = 0;
        for (const auto& f : bridge.frames()) {
            for (size_t c = 0; c < 8; ++c) {
                if (f.channelStarts[c] > received) {
                    QVERIFY2(std::abs(f.widths[c] - 1500.0) <= 2.0,
                             qPrintable(QStringLiteral("channel %1 at %2 s: %3 us")
                                            .arg(c + 1)
                                            .arg(f.channelStarts[c])
                                            .arg(f.widths[c])));
                    ++after;
                } else if (f.start > 0.05 &&
                           f.channelStarts[c] + f.widths[c] * 1e-6 < received - 0.001) {
                    QVERIFY(std::abs(f.widths[c] - 1900.0) <= 2.0);  // before it: the command
                }
            }
        }
        QVERIFY(after >= 8);
    }

    void bridge_ignoresGarbageAndBrokenFrames() {
        Bridge bridge;
        QVERIFY(bridge.runUntil(0.005));  // the UART set up
        // The link's frames every 10 ms (each 3 ms on the wire, then a gap).
        const auto stream = [&](double from, double to) {
            for (double t = from; t < to - 1e-9; t += 0.010) {
                QVERIFY(bridge.runUntil(t));
                bridge.send(sbus(kCommand));
            }
        };
        stream(0.005, 0.05);
        // Garbage (with 0x0F headers inside the burst), then a frame whose end byte is wrong,
        // then one with a byte too many: none changes what goes out.
        QByteArray junk;
        for (int i = 0; i < 60; ++i) {
            junk.append(static_cast<char>(i % 7 == 3 ? 0x0F : (i * 37 + 11) & 0xFF));
        }
        QVERIFY(bridge.runUntil(0.05));
        bridge.send(junk);
        QVERIFY(bridge.runUntil(0.070));
        QByteArray broken = sbus(kNeutral);
        broken[24] = 0x42;
        bridge.send(broken);
        QVERIFY(bridge.runUntil(0.080));
        bridge.send(sbus({1900, 1900, 1900, 1900, 1900, 1900, 1900, 1900}) + QByteArray(1, '\0'));
        stream(0.090, 0.17);
        QVERIFY(bridge.runUntil(0.18));
        int frames = 0;
        for (const auto& f : bridge.frames()) {
            if (f.start > 0.04) {
                ++frames;
                QVERIFY2(
                    within(f.widths, kCommand, 2.0),
                    qPrintable(
                        QStringLiteral("frame at %1 s: ch1 %2 us").arg(f.start).arg(f.widths[0])));
            }
        }
        QVERIFY(frames >= 5);
    }

    void bridge_putsOutNothingFromPureGarbage() {
        // Bursts of random bytes of random length with random quiet gaps, as a loose wire or a
        // wrong baud rate gives: every pulse that goes out is neutral.
        for (unsigned seed = 1; seed <= 12; ++seed) {
            Bridge bridge;
            QVERIFY(bridge.runUntil(0.005));
            std::uint32_t state = seed * 2654435761u;
            const auto next = [&state] {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                return state;
            };
            double t = 0.005;
            while (t < 0.4) {
                QByteArray burst;
                const int length = 1 + static_cast<int>(next() % 80);
                for (int i = 0; i < length; ++i) {
                    // Headers and end bytes more often than chance, to look like frames.
                    const std::uint32_t r = next();
                    burst.append(static_cast<char>(r % 5 == 0 ? 0x0F : r % 5 == 1 ? 0x00 : r >> 8));
                }
                bridge.send(burst);
                t += length * 120e-6 + (200 + next() % 4800) * 1e-6;
                QVERIFY(bridge.runUntil(t));
            }
            QVERIFY(bridge.runUntil(0.45));
            for (const auto& f : bridge.frames()) {
                QVERIFY2(within(f.widths, kNeutral, 2.0),
                         qPrintable(QStringLiteral("seed %1: frame at %2 s: ch1 %3 us, ch2 %4 us")
                                        .arg(seed)
                                        .arg(f.start)
                                        .arg(f.widths[0])
                                        .arg(f.widths[1])));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestPpmBridge)
#include "test_ppm_bridge.moc"
