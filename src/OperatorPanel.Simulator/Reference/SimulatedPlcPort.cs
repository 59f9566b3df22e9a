using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The PLC's port as RCV sees it (SMB87 en+sc+ec, SMB88 '&lt;', SMB89 '&gt;', SMB94 255): idle until '&lt;';
/// then every character is stored, a second '&lt;' included (the handler, not RCV, restarts at the last '&lt;'),
/// until '&gt;' ends the message; 255 characters without '&gt;' end the receive by count and the message is dropped
/// (its characters still reached the buffer). Transport-agnostic: bytes in, reply frames out.
/// </summary>
public sealed class SimulatedPlcPort
{
    private readonly List<byte> _buffer = new(ProtocolLimits.MaxFrameChars);

    public SimulatedPlcPort(ReferencePlc plc)
    {
        ArgumentNullException.ThrowIfNull(plc);
        Plc = plc;
    }

    public ReferencePlc Plc { get; }

    /// <summary>How long after the request's '&gt;' the reply goes out (timed interrupt 0, SMB34).</summary>
    public TimeSpan ReplyDelay => TimeSpan.FromMilliseconds(Plc.Config.ReplyDelayMs);

    /// <summary>Receives ended by the character count (status c in SMB86) and dropped.</summary>
    public int DroppedReceives { get; private set; }

    /// <summary>Frames received complete, whether answered or not.</summary>
    public int ReceivedFrames { get; private set; }

    public IReadOnlyList<byte[]> Feed(ReadOnlySpan<byte> bytes)
    {
        var replies = new List<byte[]>();
        foreach (var b in bytes)
        {
            if (_buffer.Count == 0 && b != FrameCodec.StartChar)
            {
                continue;
            }

            _buffer.Add(b);
            if (_buffer.Count > 1 && b == FrameCodec.EndChar)
            {
                ReceivedFrames++;
                var reply = Plc.HandleFrame(_buffer.ToArray());
                _buffer.Clear();
                if (reply is not null)
                {
                    replies.Add(reply);
                }
            }
            else if (_buffer.Count == ProtocolLimits.MaxFrameChars)
            {
                DroppedReceives++;
                Plc.ReceiveDropped(_buffer.Count);
                _buffer.Clear();
            }
        }

        return replies;
    }
}
