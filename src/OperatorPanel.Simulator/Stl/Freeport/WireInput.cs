using OperatorPanel.Core.Transport;

namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// The line as one port's receiver sees it: every burst from the PC and the other stations (levels combine as on a
/// wired-AND, so a collision garbles), decoded like a UART at the receiver's own settings. The receiver syncs on the
/// start bits of the characters sent and samples each bit in its middle at its own baud, so a sender with other
/// settings yields wrong characters, parity and framing errors, not a working link by accident.
/// </summary>
internal sealed class WireInput
{
    /// <summary>False starts (a start bit sampled high) skipped before giving up on this call.</summary>
    private const int MaxFalseStarts = 64;

    private readonly List<WireBurst> _bursts = [];

    public void Add(WireBurst burst)
    {
        if (!_bursts.Contains(burst))
        {
            _bursts.Add(burst);
        }
    }

    /// <summary>Forgets bursts that ended a character time or more before <paramref name="before"/>.</summary>
    public void Prune(TimeSpan before) => _bursts.RemoveAll(b => b.End + b.Settings.CharacterTime <= before);

    /// <summary>The next character whose start bit begins at or after <paramref name="readyAt"/>, or null.</summary>
    public ReceivedCharacter? Next(LineSettings receiver, TimeSpan readyAt)
    {
        var from = readyAt;
        for (var attempt = 0; attempt < MaxFalseStarts; attempt++)
        {
            if (!TryFindStart(from, out var burst, out var index, out var start))
            {
                return null;
            }

            if (Sample(start, receiver, 0))
            {
                from = start + TimeSpan.FromTicks(1);
                continue;
            }

            return Decode(receiver, burst, index, start);
        }

        return null;
    }

    private bool TryFindStart(TimeSpan from, out WireBurst burst, out int index, out TimeSpan start)
    {
        burst = null!;
        index = 0;
        start = TimeSpan.MaxValue;
        foreach (var candidate in _bursts)
        {
            var i = candidate.IsBreak ? (candidate.Start >= from ? 0 : 1) : candidate.FirstCharacterAtOrAfter(from);
            var limit = candidate.IsBreak ? 1 : candidate.Count;
            if (i < limit && candidate.CharacterStart(i) < start)
            {
                (burst, index, start) = (candidate, i, candidate.CharacterStart(i));
            }
        }

        return burst is not null;
    }

    private ReceivedCharacter Decode(LineSettings receiver, WireBurst burst, int index, TimeSpan start)
    {
        var value = 0;
        var ones = 0;
        for (var bit = 0; bit < receiver.DataBits; bit++)
        {
            if (Sample(start, receiver, 1 + bit))
            {
                value |= 1 << bit;
                ones++;
            }
        }

        var position = 1 + receiver.DataBits;
        var parityOk = true;
        var parityBit = false;
        if (receiver.Parity != Parity.None)
        {
            parityBit = Sample(start, receiver, position++);
            ones += parityBit ? 1 : 0;
            parityOk = (ones % 2 == 0) == (receiver.Parity == Parity.Even);
        }

        var stop = Sample(start, receiver, position);
        var bits = receiver.BitsPerCharacter;
        if (!stop && value == 0 && !parityBit)
        {
            var lowUntil = burst.IsBreak ? burst.End : start + receiver.Bits(bits);
            return new ReceivedCharacter(0, start, lowUntil, lowUntil, Error: true, IsBreak: true);
        }

        // Same settings and synchronised on this very character: it is received exactly when its stop bit ends.
        var at = burst.Settings == receiver && !burst.IsBreak ? burst.CharacterEnd(index) : start + receiver.Bits(bits);
        var readyAt = start + receiver.HalfBits((2L * bits) - 1);
        return new ReceivedCharacter((byte)value, start, at, readyAt, Error: !parityOk || !stop, IsBreak: false);
    }

    /// <summary>The line level in the middle of bit <paramref name="bit"/> of a character starting at <paramref name="start"/>.</summary>
    private bool Sample(TimeSpan start, LineSettings receiver, int bit)
    {
        var at = start + receiver.HalfBits((2L * bit) + 1);
        foreach (var burst in _bursts)
        {
            if (!burst.LevelAt(at))
            {
                return false;
            }
        }

        return true;
    }
}
