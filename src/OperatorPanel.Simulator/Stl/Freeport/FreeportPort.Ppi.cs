using OperatorPanel.Core.Ppi;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// The port's PPI side: whenever the program does not hold the port in Freeport (no RCV/XMT with mm = 01, STOP, the
/// handler's TERM branch), the CPU's own PPI station listens at its PPI line (8 data bits, even parity) and answers
/// the telegrams addressed to it one station delay after their last character (docs/ppi.md section 11).
/// </summary>
public sealed partial class FreeportPort
{
    private readonly PpiFrameReader _ppiReader = new();
    private PpiSlave? _ppi;
    private TimeSpan _ppiLastCharacter;

    /// <summary>The CPU's PPI station on this port, or null when the simulation has none (characters in PPI are then lost).</summary>
    public PpiSlave? Ppi => _ppi;

    /// <summary>Broken telegrams the PPI side dropped (checksum, header, end, parity or a pause inside a telegram).</summary>
    public int PpiFramesDropped { get; private set; }

    public void AttachPpi(PpiSlave slave)
    {
        ArgumentNullException.ThrowIfNull(slave);
        _ppi = slave;
    }

    private void TakePpiCharacter(ReceivedCharacter character)
    {
        var ppi = _ppi!;
        if (character.IsBreak || character.Error)
        {
            // A PROFIBUS receiver drops a telegram with a parity or framing error (the FCS cannot catch those).
            PpiFramesDropped += _ppiReader.PendingChars > 0 ? 1 : 0;
            _ppiReader.Reset();
            return;
        }

        if (_ppiReader.PendingChars > 0 && character.Start - _ppiLastCharacter > ppi.Settings.PartialFrameTimeout)
        {
            PpiFramesDropped++;
            _ppiReader.Reset();
        }

        _ppiLastCharacter = character.At;
        _ppiReader.Append([character.Value]);
        while (_ppiReader.TryTake(out var result))
        {
            if (result.Frame is not { } frame)
            {
                PpiFramesDropped++;
            }
            else if (ppi.Receive(frame) is { } reply)
            {
                SendPpi(reply, character.At + ppi.Settings.StationDelay);
            }
        }
    }

    /// <summary>Puts <paramref name="reply"/> on the line from <paramref name="at"/>; a station never answers while it is still sending.</summary>
    private void SendPpi(PpiFrame reply, TimeSpan at)
    {
        if (_transmission is not null)
        {
            return;
        }

        var burst = new WireBurst(at, _ppi!.Settings.Line, isBreak: false);
        burst.Append(PpiFrameCodec.Encode(reply));
        _transmission = new Transmission(burst) { IsPpi = true };
        Bus?.Forward(this, burst);
    }
}
