using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// One direction of a noisy line: characters go in as sent and come out as received, with <see cref="LineFaults"/>
/// drawn from a seeded generator, so the same seed and the same characters give the same faults. Only the 8 data
/// bits are flipped (a flipped start or stop bit is a framing error the UART reports; not modelled). A frame is
/// chosen for dropping at its '&lt;' as sent and dropped through its '&gt;' as sent, whatever flips do to them.
/// </summary>
public sealed class FaultInjector(LineFaults faults, int seed)
{
    private readonly Random _random = new(seed);
    private bool _droppingFrame;

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
            if (character == FrameCodec.StartChar && _random.NextDouble() < faults.FrameDropRate)
            {
                _droppingFrame = true;
                FramesDropped++;
            }

            if (_droppingFrame)
            {
                _droppingFrame = character != FrameCodec.EndChar;
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
