using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// One direction of a noisy line: characters go in as sent and come out as received, with <see cref="LineFaults"/>
/// drawn from a seeded generator, so the same seed and the same characters give the same faults. Only the 8 data
/// bits are flipped (a flipped start or stop bit is a framing error the UART reports; not modelled). A frame is
/// chosen for dropping at its '&lt;' as sent and dropped through its last byte as sent: the injector follows the
/// frames as sent by their LEN (protocol v3, docs/protocol.md section 1.6), whatever flips do to them, so a data
/// byte equal to '&lt;' inside a frame never starts a drop. A '&lt;' followed by a LEN below the shortest frame's
/// (bytes that are not a v3 frame, e.g. the v2 IDENTIFY the panel sends to recognise an older handler) is not followed.
/// </summary>
public sealed class FaultInjector(LineFaults faults, int seed)
{
    private readonly Random _random = new(seed);
    private bool _droppingFrame;

    /// <summary>Bytes of the current frame as sent still to come; 0 between frames, -1 right after its '&lt;'.</summary>
    private int _frameLeft;

    public long Characters { get; private set; }

    public long BitsFlipped { get; private set; }

    public long CharactersDropped { get; private set; }

    public long FramesDropped { get; private set; }

    public byte[] Pass(ReadOnlySpan<byte> sent)
    {
        var received = new List<byte>(sent.Length);
        foreach (var character in sent)
        {
            Characters++;
            var starts = Follow(character);
            if (starts && _random.NextDouble() < faults.FrameDropRate)
            {
                _droppingFrame = true;
                FramesDropped++;
            }

            if (_droppingFrame)
            {
                _droppingFrame = _frameLeft != 0;
                continue;
            }

            if (_random.NextDouble() < faults.CharacterDropRate)
            {
                CharactersDropped++;
                continue;
            }

            received.Add(Flip(character));
        }

        return [.. received];
    }

    /// <summary>Follows the frames as sent; true when <paramref name="character"/> is a frame's '&lt;'.</summary>
    private bool Follow(byte character)
    {
        switch (_frameLeft)
        {
            case 0:
                _frameLeft = character == Limits.Start ? -1 : 0;
                return character == Limits.Start;
            case -1:
                // LEN counts every byte of the frame: '<' and LEN are behind us.
                _frameLeft = character >= Codec.MinRequestLen ? character - 2 : 0;
                return false;
            default:
                _frameLeft--;
                return false;
        }
    }

    private byte Flip(byte character)
    {
        for (var bit = 0; bit < 8; bit++)
        {
            if (_random.NextDouble() < faults.BitFlipRate)
            {
                character ^= (byte)(1 << bit);
                BitsFlipped++;
            }
        }

        return character;
    }
}
