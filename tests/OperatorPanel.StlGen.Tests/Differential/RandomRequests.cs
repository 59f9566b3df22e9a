using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// Seeded random exchanges: valid and invalid requests of every command (items at every area edge, not-writable areas,
/// protected SM bytes, BIT/VALUE errors, list ids 0-5, COUNT 0 and above 20, bad lengths), frame-level damage (bad
/// check characters, flipped bits, odd or short body, lowercase or illegal characters, truncated), overheard replies and
/// other stations' frames, the remains of a cut-off frame before a frame, noise between frames and a stray '&lt;'. Reads and writes that would be valid keep clear of the handler's V bytes
/// and of the volatile SM bytes (see <see cref="DifferentialHarness"/>), and in a merged run of the user's bytes.
/// </summary>
internal sealed class RandomRequests(Random random, DifferentialHarness harness, int station, int charTimeoutMs)
{
    private static readonly byte[] Noise = "0123456789ABCDEF>xz \r\n?"u8.ToArray();

    public List<WireChunk> Next()
    {
        var frame = FrameCodec.Encode(new FreeportFrame(Station(), (byte)random.Next(256), Command(out var payload), payload));
        frame = Damage(frame);
        var chunks = new List<WireChunk>();
        switch (random.Next(14))
        {
            case 0:
                chunks.Add(WireChunk.Now(NoiseChars(random.Next(1, 12))));
                break;
            case 1:
                // A stray '<' (and noise) runs into the frame: one message, silence, lists cleared if long enough.
                chunks.Add(WireChunk.Now([(byte)'<', .. NoiseChars(random.Next(0, 6)).Where(c => c != '>')]));
                break;
            case 3 when random.Next(4) == 0:
                // More than 255 characters: RCV ends at its maximum count, the rest (no '<') is dropped.
                chunks.Add(WireChunk.Now([(byte)'<', .. Enumerable.Range(0, random.Next(255, 300)).Select(_ => (byte)"0123456789ABCDEF"[random.Next(16)]), (byte)'>']));
                break;
            case 2 or 4:
                // A truncated frame, this one or another station's: ended by the inter-character timer, or (timer off)
                // continued by the next frame, which is answered from its '<' unless the cut-off frame's header was
                // another station's (early silence on the first '<').
                var cutOff = random.Next(2) == 0 ? frame : FrameCodec.Encode(new FreeportFrame(Station(), (byte)random.Next(256), Command(out var other), other));
                var cut = cutOff[..random.Next(1, cutOff.Length - 1)];
                chunks.Add(WireChunk.Now(cut));
                if (charTimeoutMs > 0)
                {
                    chunks.Add(new WireChunk([], TimeSpan.FromMilliseconds(charTimeoutMs + 10)));
                }

                break;
            default:
                break;
        }

        chunks.Add(new WireChunk(frame, chunks.Count > 0 && charTimeoutMs > 0 ? TimeSpan.FromMilliseconds(charTimeoutMs + 10) : TimeSpan.Zero));
        return chunks;
    }

    private byte Station() => random.Next(12) switch
    {
        0 => (byte)random.Next(256),
        1 => (byte)(station % 126 + 1),
        _ => (byte)station,
    };

    private byte Command(out ImmutableArray<byte> payload)
    {
        var p = new List<byte>();
        byte cmd = random.Next(20) switch
        {
            0 => 1,
            1 => UnknownCommand(),
            2 => 0,
            >= 3 and <= 7 => 2,
            8 or 9 or 10 => 5,
            11 or 12 or 13 => 6,
            14 or 15 or 16 => 3,
            _ => 4,
        };
        switch (cmd)
        {
            case 1:
                break;
            case 2 or 5:
                if (cmd == 5)
                {
                    p.Add((byte)random.Next(0, 6));
                }

                var n = random.Next(10) == 0 ? random.Next(0, 23) : random.Next(1, random.Next(3) == 0 ? 21 : 6);
                p.Add((byte)n);
                for (var i = 0; i < n; i++)
                {
                    Item(p, random.Next(5) == 0 ? random.Next(1, 120) : random.Next(1, 9), write: false);
                }

                break;
            case 6:
                p.Add((byte)random.Next(0, 6));
                break;
            case 3:
                var length = random.Next(6) == 0 ? random.Next(0, 120) : random.Next(1, 20);
                Item(p, length, write: true);
                for (var i = 0; i < length; i++)
                {
                    p.Add((byte)random.Next(256));
                }

                break;
            default:
                Item(p, 1, write: true);
                p[^1] = (byte)(random.Next(8) == 0 ? random.Next(8, 256) : random.Next(8));
                p.Add((byte)(random.Next(8) == 0 ? random.Next(2, 256) : random.Next(2)));
                break;
        }

        if (random.Next(20) == 0 && p.Count > 0)
        {
            // Bad length: one byte too many or too few.
            if (random.Next(2) == 0)
            {
                p.Add((byte)random.Next(256));
            }
            else
            {
                p.RemoveAt(p.Count - 1);
            }
        }

        if (random.Next(25) == 0)
        {
            cmd |= FreeportFrame.ReplyBit;
        }

        // The longest frame is 255 characters (121 payload bytes); longer lines come from the overlong case.
        payload = [.. p.Take(ProtocolLimits.MaxBodyBytes - FreeportFrame.OverheadBytes)];
        return cmd;
    }

    /// <summary>
    /// A command code this handler does not know (error 05): 07 STOP (generated without it) and 0A-FF. 08 and 09 are
    /// left out: both answer them.
    /// </summary>
    private byte UnknownCommand()
    {
        var code = random.Next(9, 256);
        return (byte)(code == 9 ? 7 : code);
    }

    /// <summary>AREA OFFSET(2) LENGTH; for WRITE BIT the LENGTH byte becomes BIT (the caller overwrites it).</summary>
    private void Item(List<byte> p, int length, bool write)
    {
        var area = random.Next(12) switch
        {
            0 => (byte)random.Next(6, 256),
            1 => (byte)0,
            _ => (byte)random.Next(1, 6),
        };
        var size = area is >= 1 and <= 5 ? harness.Reference.AreaBytes((ProtocolArea)area) : 64;
        var span = Math.Max(length, 1);
        var offset = random.Next(10) switch
        {
            0 => size - span + 1,
            1 => size - span,
            2 => size,
            3 => random.Next(65536),
            _ => random.Next(Math.Max(1, size - span + 1)),
        };
        offset = Math.Clamp(offset, 0, 65535);
        if (offset + span <= size && !Comparable(area, offset, span))
        {
            offset = area == 4 ? Below(span) : 30 + random.Next(20);
            if (area == 5 && write)
            {
                offset = random.Next(3) == 0 ? random.Next(0, 36) : 36 + random.Next(40);
            }

            // Still in range and touching bytes that cannot be compared: make it the area-edge error instead.
            offset = offset + span <= size && !Comparable(area, offset, span) ? size : offset;
        }

        p.Add(area);
        p.Add((byte)(offset >> 8));
        p.Add((byte)offset);
        p.Add((byte)length);
    }

    private bool Comparable(byte area, int offset, int span) => !harness.User.Touches((ProtocolArea)area, offset, offset + span - 1) && area switch
    {
        4 => !harness.IsReserved(offset, offset + span - 1),
        5 => !Enumerable.Range(offset, span).Any(DifferentialHarness.IsVolatileSm),
        _ => true,
    };

    /// <summary>A V range clear of the handler's bytes: below them if there is room, else above.</summary>
    private int Below(int span) => harness.ReservedFirst >= span
        ? random.Next(harness.ReservedFirst - span + 1)
        : harness.ReservedLast + 1 + random.Next(Math.Max(1, harness.Reference.AreaBytes(ProtocolArea.V) - harness.ReservedLast - span));

    private byte[] Damage(byte[] frame)
    {
        var f = frame.ToList();
        switch (random.Next(30))
        {
            case 0:
                f[^2] = (byte)(f[^2] == '0' ? '1' : '0');
                break;
            case 1 when f.Count > 4:
                f.RemoveAt(f.Count - 2);
                break;
            case 2:
                f = [(byte)'<', .. f.Skip(1).Take(random.Next(0, 8)), (byte)'>'];
                break;
            case 3 when f.Count > 4:
                var i = random.Next(1, f.Count - 1);
                f[i] = f[i] is >= (byte)'A' and <= (byte)'F' ? (byte)(f[i] + 32) : (byte)'G';
                break;
            case 4:
                // A check character's low bit: still 16#60-16#6F, but another CRC.
                f[^(1 + random.Next(1, CheckCharacters.Count + 1))] ^= 0x01;
                break;
            case 5 or 6:
                // One bit of a body character flipped (noise the CRC detects).
                f[random.Next(1, f.Count - 1 - CheckCharacters.Count)] ^= (byte)(1 << random.Next(7));
                break;
            default:
                break;
        }

        return [.. f];
    }

    private byte[] NoiseChars(int n) => [.. Enumerable.Range(0, n).Select(_ => Noise[random.Next(Noise.Length)])];
}
