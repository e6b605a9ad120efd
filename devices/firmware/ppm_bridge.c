/*
 * The trainer-port bridge: SBUS frames from the transmitter link on the UART (RX, Arduino D0;
 * 100000 baud 8E2, not inverted) in, 8-channel PPM for a transmitter's trainer port out on
 * OC1A (PB1, Arduino D9). ATmega328P at 16 MHz (Arduino Nano / Uno class).
 *
 * PPM: the line idles low; every channel starts with a 300 us high mark, and the time from one
 * rising edge to the next is the channel's pulse width (988..2012 us); after channel 8 the line
 * stays low until the frame's 22.5 ms are up. Edges come from the timer's output-compare
 * hardware (no interrupt latency in them): Timer 1 counts 0.5 us ticks, each compare match
 * toggles OC1A, and its interrupt only loads the next edge's time.
 *
 * Safety:
 *  - a frame with the SBUS failsafe flag is honoured at once: its channel values (the link's
 *    failsafe: throttle neutral, steering centred) replace the ones being sent mid-frame;
 *  - silence: if no valid frame came for 10 PPM frames (225 ms), every channel goes to
 *    1500 us (neutral) until frames come again;
 *  - a frame is 25 bytes between two quiet gaps of 2 ms or more (SBUS has no checksum: the
 *    gaps, the 0x0F header right after one and the 0x00 end byte are all there is to go by); a
 *    0x0F inside a burst starts nothing;
 *  - a corrupt frame (parity or framing error, wrong header or end byte, more or fewer than 25
 *    bytes between gaps) is dropped whole, and after one (and at power-on) two good frames in a
 *    row must come before their values are sent, so garbage that looks like one frame by chance
 *    never reaches the trainer port;
 *  - the chip's watchdog (250 ms) resets a hung program, which starts again at neutral.
 */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/wdt.h>
#include <stdint.h>

#define CHANNELS 8
#define TICKS_PER_US 2u
#define FRAME_TICKS (22500u * TICKS_PER_US)
#define MARK_TICKS (300u * TICKS_PER_US)
#define NEUTRAL_TICKS (1500u * TICKS_PER_US)
#define SILENT_FRAMES 10u
#define SBUS_SIZE 25u

/* What the next PPM frame sends, and what is being sent now [ticks]. */
static volatile uint16_t pending[CHANNELS];
static volatile uint16_t active[CHANNELS];
/* PPM frames started since the last valid SBUS frame. */
static volatile uint8_t silent = SILENT_FRAMES;
/* The SBUS frame being received: its bytes since the last gap (SBUS_SIZE + 1: dropped until the
   next gap), and whether 25 good bytes are waiting for the gap that ends them. */
static uint8_t frame[SBUS_SIZE];
static volatile uint8_t received;
static volatile uint8_t complete;
static volatile uint8_t lastByteTick;
/* Good frames in a row since a bad one (saturating): values are sent from the second on. */
static uint8_t goodInARow;
/* Set by the receive interrupt when it dropped a frame; the main loop restarts the count. */
static volatile uint8_t dropped = 1;
static volatile uint8_t tick; /* Timer 0 overflows: about 1 ms each */

/* PPM state: the rising edge that starts the channel being sent, and which. */
static uint16_t frameStart;
static uint16_t rise;
static uint8_t channel;
static uint8_t high;

/* An SBUS value (172..1811 for 988..2012 us, 1024/1639 us per step) in 0.5 us ticks, clamped
   to 900..2100 us. 5/8 us per step is 0.02 % off the true slope (0.4 us at the ends); shifts
   and 16-bit sums only, no division in the way of the PPM timing. */
static uint16_t sbusToTicks(uint16_t value) {
    if (value < 32) {
        value = 32; /* (900 us) */
    } else if (value > 2000) {
        value = 2000;
    }
    int16_t ticks = (int16_t)(1976 + (((int16_t)value - 172) * 5 + 2) / 4);
    if (ticks < 1800) {
        ticks = 1800;
    } else if (ticks > 4200) {
        ticks = 4200;
    }
    return (uint16_t)ticks;
}

/* A complete frame the main loop took over from the receive interrupt, to decode outside any
   interrupt (decoding in one would hold back the PPM's edge interrupt). */
static uint8_t ready[SBUS_SIZE];

static void takeFrame(void) {
    uint16_t values[CHANNELS];
    /* 16 x 11 bits, least significant bit first, from byte 1; the first 8 channels. */
    uint32_t bits = 0;
    uint8_t have = 0, byte = 1;
    for (uint8_t c = 0; c < CHANNELS; ++c) {
        while (have < 11) {
            bits |= (uint32_t)ready[byte++] << have;
            have += 8;
        }
        values[c] = sbusToTicks((uint16_t)(bits & 0x7FF));
        bits >>= 11;
        have -= 11;
    }
    const uint8_t failsafe = (ready[23] & 0x08) != 0;
    cli();
    for (uint8_t c = 0; c < CHANNELS; ++c) {
        pending[c] = values[c];
        if (failsafe) {
            active[c] = values[c]; /* at once: the channels still to come in this frame */
        }
    }
    silent = 0;
    sei();
}

/* After a watchdog reset the watchdog stays on at its shortest period: off at once, before the
   C start-up code can take longer than that. */
void earlyWatchdogOff(void) __attribute__((naked, used, section(".init3")));
void earlyWatchdogOff(void) {
    MCUSR = 0;
    wdt_disable();
}

/* Drops the frame being received: nothing more is taken until the next gap. */
static void dropFrame(void) {
    if (received != 0 || complete) {
        dropped = 1;
    }
    received = SBUS_SIZE + 1;
    complete = 0;
}

ISR(USART_RX_vect) {
    const uint8_t status = UCSR0A;
    const uint8_t byte = UDR0;
    const uint8_t now = tick;
    /* A gap of 2 ms or more starts a new frame (frames come with a gap of 3 ms or more, their
       bytes back to back). A complete frame the main loop had not taken yet when its gap ended
       (within microseconds of the tick) is let go: the next one is taken. */
    if ((uint8_t)(now - lastByteTick) >= 2) {
        complete = 0;
        received = 0;
    }
    lastByteTick = now;
    if (status & ((1 << FE0) | (1 << DOR0) | (1 << UPE0))) {
        dropFrame(); /* the rest of this frame: wait for the next gap */
        dropped = 1;
        return;
    }
    if (received > SBUS_SIZE) {
        return; /* dropped: until the next gap */
    }
    if (received == SBUS_SIZE) {
        dropFrame(); /* a 26th byte before any gap: not a frame */
        return;
    }
    if (received == 0 && byte != 0x0F) {
        dropFrame(); /* the first byte after a gap is no header: not a frame */
        return;
    }
    frame[received++] = byte;
    if (received == SBUS_SIZE) {
        if (frame[24] == 0x00) {
            complete = 1; /* taken once the line stays quiet for the gap */
        } else {
            dropFrame();
        }
    }
}

/* A complete frame followed by its gap, from the main loop: handed to takeFrame() once two good
   ones came in a row. Interrupts are off while it is copied. */
static uint8_t takeCompleteFrame(void) {
    uint8_t take = 0;
    cli();
    if (dropped) {
        dropped = 0;
        goodInARow = 0;
    }
    if (complete && (uint8_t)(tick - lastByteTick) >= 2) {
        complete = 0;
        received = SBUS_SIZE + 1; /* until the next gap */
        if (goodInARow < 255) {
            ++goodInARow;
        }
        if (goodInARow >= 2) {
            for (uint8_t i = 0; i < SBUS_SIZE; ++i) {
                ready[i] = frame[i];
            }
            take = 1;
        }
    }
    sei();
    return take;
}

ISR(TIMER0_OVF_vect) { ++tick; }

ISR(TIMER1_COMPA_vect) {
    if (high) {
        /* The mark just started (a rising edge at OCR1A): end it 300 us later. */
        OCR1A = rise + MARK_TICKS;
        high = 0;
        return;
    }
    /* The mark just ended: the next rising edge starts the next channel, or the next frame. */
    if (channel < CHANNELS) {
        rise += active[channel];
        ++channel;
    } else {
        frameStart += FRAME_TICKS;
        rise = frameStart;
        channel = 0;
        /* A new frame: take the newest values, or neutral after silence. */
        if (silent < 255) {
            ++silent;
        }
        for (uint8_t c = 0; c < CHANNELS; ++c) {
            active[c] = silent >= SILENT_FRAMES ? NEUTRAL_TICKS : pending[c];
        }
    }
    OCR1A = rise;
    high = 1;
}

int main(void) {
    wdt_enable(WDTO_250MS);
    for (uint8_t c = 0; c < CHANNELS; ++c) {
        pending[c] = NEUTRAL_TICKS;
        active[c] = NEUTRAL_TICKS;
    }
    /* OC1A (PB1) an output, low. */
    PORTB &= (uint8_t) ~(1 << PB1);
    DDRB |= (1 << PB1);
    /* UART: 100000 baud (16 MHz / 16 / 10), 8 data bits, even parity, 2 stop bits, receive
       with its interrupt. */
    UBRR0H = 0;
    UBRR0L = 9;
    UCSR0A = 0;
    UCSR0C = (1 << UPM01) | (1 << USBS0) | (1 << UCSZ01) | (1 << UCSZ00);
    UCSR0B = (1 << RXEN0) | (1 << RXCIE0);
    /* Timer 0: /64, overflow every 1.024 ms. */
    TCCR0A = 0;
    TCCR0B = (1 << CS01) | (1 << CS00);
    TIMSK0 = (1 << TOIE0);
    /* Timer 1: normal mode, /8 (0.5 us ticks); the first frame starts 1 ms from now. The
       first edge is loaded before the compare output is connected, so no match at the
       counter's start toggles it early. */
    TCNT1 = 0;
    frameStart = 1000u * TICKS_PER_US;
    rise = frameStart;
    channel = 0;
    high = 1;
    OCR1A = rise;
    TCCR1A = (1 << COM1A0); /* toggle OC1A on every match: the edges alternate */
    /* The compare output must start low (the first match is a rising edge); a forced match
       toggles it if it does not (PINB reads the pin the compare unit drives). */
    if (PINB & (1 << PB1)) {
        TCCR1C = (1 << FOC1A);
    }
    TIMSK1 = (1 << OCIE1A);
    TCCR1B = (1 << CS11);
    sei();
    for (;;) {
        wdt_reset();
        if (takeCompleteFrame()) {
            takeFrame();
        }
    }
}
