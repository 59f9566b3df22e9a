using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// A plain model of an S7-200 running the protocol handler, following the normative processing order of
/// docs/protocol.md step by step. The generated STL must answer every frame byte for byte as this does.
/// </summary>
public sealed class ReferencePlc : IRequestTarget
{
    /// <summary>SMB6 holds the CPU type in bits 4-7 (seed 002 Table C-7).</summary>
    private const int Smb6 = 6;

    /// <summary>SMW22 last, SMW24 minimum, SMW26 maximum scan time in ms (seed 002 Table C-9).</summary>
    private const int Smw22 = 22;

    private readonly byte[] _panelOwnedOutputs;
    private ModeSwitch _switch;
    private bool _scanned;

    public ReferencePlc(HandlerConfig config)
    {
        ArgumentNullException.ThrowIfNull(config);
        Config = config;
        Memory = new PlcMemory(config.Cpu);
        Memory.SM[Smb6] = config.Cpu.CpuIdCode;
        _panelOwnedOutputs = new byte[Memory.Q.Length];
        Switch = ModeSwitch.Run;
    }

    public HandlerConfig Config { get; }

    public PlcMemory Memory { get; }

    public OperatingMode Mode { get; set; } = OperatingMode.Run;

    /// <summary>The mode switch; SM0.7 follows it.</summary>
    public ModeSwitch Switch
    {
        get => _switch;
        set
        {
            _switch = value;
            Memory.SetBit(ProtocolArea.SM, 0, 7, value == ModeSwitch.Run);
        }
    }

    /// <summary>A frame '&lt;'..'&gt;' as received; the reply frame to send, or null for silence.</summary>
    public byte[]? HandleFrame(ReadOnlySpan<byte> frameChars)
    {
        // STOP, or TERM with SM0.7 off: the port speaks PPI again and ignores Freeport frames.
        if (Mode == OperatingMode.Stop || Switch != ModeSwitch.Run)
        {
            return null;
        }

        // Steps 2-4: malformed, another station's, or a reply overheard on the bus -> silence.
        if (!FrameCodec.TryDecode(frameChars, out var frame, out _) || frame.Station != Config.Station.Address || frame.IsReply)
        {
            return null;
        }

        // Steps 5-6.
        if (!RequestCodec.TryParse(frame, this, out var request, out var error))
        {
            return error == ProtocolError.None ? null : Reply(frame, [(byte)error]);
        }

        // Step 7: execute; the caller sends the reply after the configured delay.
        return Reply(frame, [0, .. Execute(request)]);
    }

    /// <summary>Records one finished scan of <paramref name="milliseconds"/> in SMW22/SMW24/SMW26.</summary>
    public void CompleteScan(ushort milliseconds)
    {
        var min = Memory.ReadWord(ProtocolArea.SM, Smw22 + 2);
        var max = Memory.ReadWord(ProtocolArea.SM, Smw22 + 4);
        Memory.WriteWord(ProtocolArea.SM, Smw22, milliseconds);
        Memory.WriteWord(ProtocolArea.SM, Smw22 + 2, _scanned ? Math.Min(min, milliseconds) : milliseconds);
        Memory.WriteWord(ProtocolArea.SM, Smw22 + 4, _scanned ? Math.Max(max, milliseconds) : milliseconds);
        _scanned = true;
    }

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
            if (area == ProtocolArea.SM && Config.IsProtectedSmByte(i))
            {
                return false;
            }
        }

        return true;
    }

    private static byte[] Reply(FreeportFrame request, ImmutableArray<byte> payload) =>
        FrameCodec.Encode(new FreeportFrame(request.Station, request.Sequence, (byte)(request.Command | FreeportFrame.ReplyBit), payload));

    private byte[] Execute(PlcRequest request)
    {
        switch (request)
        {
            case ReadRequest read:
                return [.. read.Items.SelectMany(item => Memory.Area(item.Area).Skip(item.Offset).Take(item.Length))];
            case WriteBlockRequest write:
                write.Data.CopyTo(Memory.Area(write.Area), write.Offset);
                if (write.Area == ProtocolArea.Q)
                {
                    _panelOwnedOutputs.AsSpan(write.Offset, write.Data.Length).Fill(0xFF);
                }

                return Memory.Area(write.Area).AsSpan(write.Offset, write.Data.Length).ToArray();
            case WriteBitRequest bit:
                // ORB / ANDB on the byte itself: the other seven bits stay as the program left them.
                Memory.SetBit(bit.Area, bit.Offset, bit.Bit, bit.Value);
                if (bit.Area == ProtocolArea.Q)
                {
                    _panelOwnedOutputs[bit.Offset] |= (byte)(1 << bit.Bit);
                }

                return [Memory.Area(bit.Area)[bit.Offset]];
            default:
                return Identify();
        }
    }

    private byte[] Identify() =>
    [
        HandlerIdentity.ProtocolVersion,
        HandlerIdentity.HandlerRevision,
        HandlerIdentity.CpuModelCode(Config.Cpu.Model),
        HandlerIdentity.CpuRevisionCode(Config.Cpu.Revision),
        Config.WriteMask,
        HandlerIdentity.MaxReadData,
        Config.ReplyDelayMs,
        Memory.SM[Smb6],
        Memory.GetBit(ProtocolArea.SM, 0, 7) ? HandlerIdentity.ModeSwitchRunFlag : (byte)0,
        .. Memory.SM.AsSpan(Smw22, 6),
    ];
}
