#pragma once

#include "framing.h"
#include "streamframer.h"

#include <vector>

namespace mbscope {

// RTU frames (MODBUS over Serial Line V1.02, 2.5.1) cut out without timing where the bytes allow:
// the unit id, function code and byte count predict the length (pdusize), and the CRC confirms it.
// Direction::Auto (a sniffer on a bus carrying both) tries the request and the response rule and
// takes the shortest one whose CRC is valid.
//
// At a frame boundary (start, after a frame, after a silence):
// - a known code waits for the predicted length; a wrong CRC starts a resynchronisation;
// - a code without a length rule (user-defined, reserved, 08/0000 echo, 2B/0D ...) is accepted at
//   the first length (4..256) where the CRC is valid, or ends at the next silence (Unverified).
// Resynchronisation (after a wrong CRC or an impossible code) searches the following starts for
// the frame with a valid CRC that ends first; codes without a length rule are skipped then
// (NoLengthRule), since only a silence can tell where such a frame starts. Skipped bytes form one
// run with the reason of its first byte. The decisions depend only on the bytes and silences,
// never on how the bytes were chunked. Unit ids are not judged (the dissector flags reserved
// ones); the CRC decides, so about one start in 65536 that fits a length rule passes by chance.
class RtuFramer final : public StreamFramer
{
public:
    static constexpr int kMaxAduSize = 256; // Serial Line V1.02, 2.5.1.1

    explicit RtuFramer(Direction direction = Direction::Auto);

    [[nodiscard]] Direction direction() const { return m_direction; }
    [[nodiscard]] bool isSearching() const override { return !m_atBoundary; }

    // flushOnSilence(): at a boundary, pending bytes become a frame: Unverified for a code without
    // a length rule, Truncated for a known code whose predicted length did not arrive (so that the
    // dissector can say what is missing). After garbage, or when fewer than 2 bytes or an impossible
    // function code are pending, they are skipped as Incomplete. Either way a boundary follows.
    //
    // Flushes when t3.5 has passed since the last byte was fed (needs a baud rate and timestamps);
    // without them it flushes at once. Returns whether it flushed.
    bool onSilence(qint64 nowNs) override;
    void setBaudRate(int baud) { m_baud = baud; }
    // A slave reading its master's requests (the simulator's endpoints): a frame at a boundary
    // whose CRC fails is dropped whole, its predicted length skipped (ChecksumMismatch), and the
    // next byte starts a frame, as a slave on a line discards the frame the silence ended. Without
    // it (a sniffer, a master) a search follows, which passes over codes without a length rule
    // (08/0000, 2B/0E ...) until the next silence: a request of such a code sent after a bad one,
    // sooner than the silence, would be lost.
    void setDropsBadFrames(bool drops) { m_dropsBadFrames = drops; }
    [[nodiscard]] int baudRate() const { return m_baud; }

    // Character time for 11-bit characters (start, 8 data, parity or a second stop bit, stop:
    // Serial Line V1.02, 2.5.1), and the inter-character (t1.5) and inter-frame (t3.5) limits,
    // fixed at 750 us and 1750 us above 19200 baud (2.5.1.1). 0 for a baud rate <= 0.
    [[nodiscard]] static qint64 characterTimeNs(int baud);
    [[nodiscard]] static qint64 t15Ns(int baud);
    [[nodiscard]] static qint64 t35Ns(int baud);

protected:
    void process() override;
    void resetState() override;
    // After lost bytes no start is trusted: the resynchronisation's search for a valid CRC.
    // Bytes passed over then are AfterGap: the rest of a frame the gap cut, not a bad frame.
    void startSearch() override
    {
        beginResync();
        m_afterGap = true;
    }
    void flushPending() override;

private:
    enum class Verdict : quint8 { Accept, Wait, Reject };
    struct Decision {
        Verdict verdict = Verdict::Wait;
        qsizetype length = 0;                             // Accept
        SkipReason reason = SkipReason::ChecksumMismatch; // Reject
        qsizetype needed = 2;                             // Wait: bytes from the start that may change it
        qsizetype badLength = 0;                          // Reject for a CRC that fails: the predicted length
    };
    // What a frame starting at bytes[0] is, from the bytes present.
    [[nodiscard]] Decision decide(QByteArrayView bytes, bool atBoundary);
    [[nodiscard]] bool resynchronise();
    void beginResync();
    void endResync();
    struct Event {
        qint64 at;    // stream offset up to which bytes must be delivered
        qint64 start; // the start to judge again then
    };
    [[nodiscard]] bool isImpossible(quint8 functionCode) const;
    [[nodiscard]] bool hasLengthRule(QByteArrayView bytes) const;
    [[nodiscard]] qsizetype predictedLength(QByteArrayView bytes) const;

    Direction m_direction;
    int m_baud = 0;
    bool m_dropsBadFrames = false;
    bool m_atBoundary = true; // false while resynchronising
    bool m_afterGap = false;  // resynchronising after restartAfterGap()
    qsizetype m_crcScanned = 0; // lengths already tried for a code without a length rule
    // While resynchronising: the verdict for each start from m_probeOrigin on, the bytes delivered
    // so far (a stream offset), and when each waiting start must be judged again.
    QList<Decision> m_probes;
    qint64 m_probeOrigin = 0;
    qint64 m_delivered = 0;
    std::vector<Event> m_events;
};

} // namespace mbscope
