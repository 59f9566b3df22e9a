using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Simulator.Stl.Ppi;

/// <summary>
/// A CPU's PPI station (docs/ppi.md sections 4 and 11): it reacts to every telegram addressed to it at once, and does
/// the S7 work only in its scan's communication phase (<see cref="Serve"/>), as C233-01 p. 4-23 says the S7-200 does.
/// A job in an SD2 request (SRD) is acknowledged with 16#E5; a poll (SD1 SRD) gets the prepared answer (SD2, FC 16#08),
/// or 16#E5 while there is none yet. Frame count rule (PROFIBUS spec part 4 p. 131): an action frame with FCV = 1 and
/// the same FCB as the same master's previous one repeats the previous data answer instead of doing anything; after a
/// 16#E5 the frame is taken afresh (a lenient choice, so a master that re-polls without toggling still gets its data).
/// Only SRD frames are answered; SDA, SDN and FDL status requests are ignored (unsupported).
/// </summary>
public sealed class PpiSlave
{
    private readonly Dictionary<byte, PpiMasterState> _masters = [];

    public PpiSlave(PpiSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        Settings = settings;
    }

    public PpiSettings Settings { get; }

    /// <summary>Jobs done (answers prepared) since power-up.</summary>
    public int JobsServed { get; private set; }

    /// <summary>Telegrams addressed to this station that it answered.</summary>
    public int FramesAnswered { get; private set; }

    /// <summary>The reaction to <paramref name="frame"/>: what to send after the station delay, or null for nothing.</summary>
    public PpiFrame? Receive(PpiFrame frame)
    {
        ArgumentNullException.ThrowIfNull(frame);
        if (frame.Kind is not (PpiFrameKind.Variable or PpiFrameKind.Fixed)
            || frame.Destination != Settings.Address
            || !PpiFunctionCode.IsSendRequestData(frame.FunctionCode))
        {
            return null;
        }

        if (!_masters.TryGetValue(frame.Source, out var master))
        {
            master = new PpiMasterState();
            _masters[frame.Source] = master;
        }

        var frameCount = PpiFunctionCode.FrameCount(frame.FunctionCode);
        if (PpiFunctionCode.HasValidFrameCount(frame.FunctionCode) && master.LastFrameCount == frameCount
            && master.LastReply is { Kind: PpiFrameKind.Variable } repeat)
        {
            FramesAnswered++;
            return repeat;
        }

        master.LastFrameCount = frameCount;
        var reply = frame.Kind == PpiFrameKind.Variable ? Accept(master, frame) : Poll(master, frame.Source);
        master.LastReply = reply;
        FramesAnswered++;
        return reply;
    }

    /// <summary>The communication phase: every acknowledged job is done on <paramref name="memory"/> and its answer prepared.</summary>
    public void Serve(IPpiMemory memory)
    {
        ArgumentNullException.ThrowIfNull(memory);
        foreach (var master in _masters.Values)
        {
            if (master.PendingRefusal is { } refusal)
            {
                master.Ready = S7AnswerCodec.Refusal(master.Pending?.Reference ?? 0, refusal.Class, refusal.Code);
            }
            else if (master.Pending is { } job)
            {
                master.Ready = PpiJobRunner.Run(job, memory, Settings.PduSize);
            }
            else
            {
                continue;
            }

            (master.Pending, master.PendingRefusal) = (null, null);
            JobsServed++;
        }
    }

    /// <summary>A new job replaces any older one of the same master that was never fetched.</summary>
    private PpiFrame Accept(PpiMasterState master, PpiFrame frame)
    {
        master.Ready = null;
        var pdu = frame.Data.AsSpan();
        if (S7JobDecoder.TryDecode(pdu, out var job, out _) && pdu.Length <= Settings.PduSize)
        {
            (master.Pending, master.PendingRefusal) = (job, null);
        }
        else
        {
            // Not a job we can read, or larger than the PDU: refused as "length fields not correct" (16#8500).
            var reference = pdu.Length >= 6 ? (ushort)((pdu[4] << 8) | pdu[5]) : (ushort)0;
            (master.Pending, master.PendingRefusal) = (new S7Job.Unsupported(reference, 0), (0x85, 0x00));
        }

        return PpiFrame.ShortAcknowledge;
    }

    private PpiFrame Poll(PpiMasterState master, byte to)
    {
        if (master.Ready is not { } answer)
        {
            return PpiFrame.ShortAcknowledge;
        }

        master.Ready = null;
        return PpiFrame.Variable(to, (byte)Settings.Address, PpiFunctionCode.ResponseDataLow, answer);
    }
}
