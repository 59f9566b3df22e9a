using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// A plain model of an S7-200 running the protocol v2 handler, following the normative processing order of
/// docs/protocol-v2.md step by step. The generated STL must answer every frame byte for byte as this does.
/// </summary>
public sealed partial class ReferencePlc : IRequestTarget, IDemoPlc
{
    /// <summary>SMB6 holds the CPU type in bits 4-7 (seed 002 Table C-7).</summary>
    private const int Smb6 = 6;

    /// <summary>SMW22 last, SMW24 minimum, SMW26 maximum scan time in ms (seed 002 Table C-9).</summary>
    private const int Smw22 = 22;

    private readonly byte[] _panelOwnedOutputs;
    private readonly ListStore _lists;
    private ModeSwitch _switch;
    private OperatingMode _mode = OperatingMode.Run;
    private readonly ScanTimes _scanTimes = new();

    public ReferencePlc(HandlerConfig config)
    {
        ArgumentNullException.ThrowIfNull(config);
        Config = config;
        _lists = new ListStore(config.CopyBytes);
        Memory = new PlcMemory(config.Cpu);
        Memory.SM[Smb6] = config.Cpu.CpuIdCode;
        _panelOwnedOutputs = new byte[Memory.Q.Length];
        Switch = ModeSwitch.Run;
    }

    public HandlerConfig Config { get; }

    public PlcMemory Memory { get; }

    /// <summary>STOP (and the first scan after it) clears every READ list and its copy.</summary>
    public OperatingMode Mode
    {
        get => _mode;
        set
        {
            _mode = value;
            _lists.Clear();
        }
    }

    /// <summary>The READ lists in the handler buffer's tail, and their READ CHANGES copies.</summary>
    public ListStore Lists => _lists;

    /// <summary>The mode switch; SM0.7 follows it.</summary>
    public ModeSwitch Switch
    {
        get => _switch;
        set
        {
            _switch = value;
            _lists.Clear();
            Memory.SetBit(ProtocolArea.SM, 0, 7, value == ModeSwitch.Run);
        }
    }

    /// <summary>
    /// A receive ended by the character count (255 characters without '&gt;'): dropped, but the characters reached
    /// the buffer, so lists below them are cleared (invalidation 1).
    /// </summary>
    public void ReceiveDropped(int count)
    {
        if (Mode == OperatingMode.Run && Switch == ModeSwitch.Run)
        {
            _lists.ClearIfReached(count);
        }
    }

    /// <summary>
    /// A message as RCV received it, first '&lt;' to '&gt;'; the reply frame to send, or null for silence. After a reply
    /// to STOP the CPU is in STOP.
    /// </summary>
    public byte[]? HandleFrame(ReadOnlySpan<byte> received)
    {
        // STOP, or TERM with SM0.7 off: the port speaks PPI again and ignores Freeport frames.
        if (Mode == OperatingMode.Stop || Switch != ModeSwitch.Run)
        {
            return null;
        }

        // Step 1, the receive interrupt: the characters sit in buffer bytes 1 .. count; reaching the list tail clears
        // every list. Then early silence on the first '<' (another station's frame, or a reply).
        _lists.ClearIfReached(received.Length);
        if (ReceivedMessage.SilencedEarly(received, Config.Station))
        {
            return null;
        }

        // Steps 2-4 on the frame from the last '<' (moved to buffer byte 1): malformed, another station's, or a reply -> silence.
        var frameChars = ReceivedMessage.LastFrame(received);
        if (!FrameCodec.TryDecode(frameChars, out var frame, out _) || frame.Station != Config.Station.Address || frame.IsReply
            || !FrameCodec.TryGetCheck(frameChars, out var check))
        {
            return null;
        }

        var reply = Answer(frame, check, out var stops);
        if (stops)
        {
            Mode = OperatingMode.Stop;
        }

        return reply;
    }

    /// <summary>Records one finished scan of <paramref name="milliseconds"/> in SMW22/SMW24/SMW26.</summary>
    public void CompleteScan(ushort milliseconds) => _scanTimes.Record(Memory, milliseconds);

    /// <summary>True when the panel has written output Qn.b; the demo program then leaves it alone.</summary>
    public bool IsOwnedByPanel(int offset, int bit) => (_panelOwnedOutputs[offset] & (1 << bit)) != 0;

    /// <summary>Hands every output the panel wrote back to the program.</summary>
    public void ReleaseOutputs() => Array.Clear(_panelOwnedOutputs);

    public int AreaBytes(ProtocolArea area) => Memory.Area(area).Length;

    public bool IsWritable(ProtocolArea area, int offset, int length)
    {
        if (!Config.MayWrite(area))
        {
            return false;
        }

        for (var i = offset; i < offset + length; i++)
        {
            if ((area == ProtocolArea.SM && Config.IsProtectedSmByte(i)) || (area == ProtocolArea.V && Config.IsHandlerVByte(i)))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>STATION SEQ CMD|16#80 STATUS REQCHECK PAYLOAD: REQCHECK is the check of the frame being answered.</summary>
    private static byte[] Reply(FreeportFrame request, ushort check, ProtocolError status, ImmutableArray<byte> payload) =>
        FrameCodec.Encode(new FreeportFrame(
            request.Station, request.Sequence, (byte)(request.Command | FreeportFrame.ReplyBit), [(byte)status, (byte)(check >> 8), (byte)check, .. payload]));
}
