using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// A plain model of an S7-200 running the protocol handler, following the normative processing order of
/// docs/protocol.md step by step. The generated STL must answer every frame byte for byte as this does.
/// </summary>
public sealed class ReferencePlc : IRequestTarget, IDemoPlc
{
    /// <summary>SMB6 holds the CPU type in bits 4-7 (seed 002 Table C-7).</summary>
    private const int Smb6 = 6;

    /// <summary>SMW22 last, SMW24 minimum, SMW26 maximum scan time in ms (seed 002 Table C-9).</summary>
    private const int Smw22 = 22;

    private readonly byte[] _panelOwnedOutputs;
    private readonly ListStore _lists = new();
    private ModeSwitch _switch;
    private OperatingMode _mode = OperatingMode.Run;
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

    /// <summary>STOP (and the first scan after it) clears every READ list.</summary>
    public OperatingMode Mode
    {
        get => _mode;
        set
        {
            _mode = value;
            _lists.Clear();
        }
    }

    /// <summary>The READ lists in the handler buffer's tail.</summary>
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

    /// <summary>A frame '&lt;'..'&gt;' as received; the reply frame to send, or null for silence.</summary>
    public byte[]? HandleFrame(ReadOnlySpan<byte> frameChars)
    {
        // STOP, or TERM with SM0.7 off: the port speaks PPI again and ignores Freeport frames.
        if (Mode == OperatingMode.Stop || Switch != ModeSwitch.Run)
        {
            return null;
        }

        // Step 1: the received characters sit in buffer bytes 1 .. count; reaching the list tail clears every list.
        _lists.ClearIfReached(frameChars.Length);

        // Steps 2-4: malformed, another station's, or a reply overheard on the bus -> silence.
        if (!FrameCodec.TryDecode(frameChars, out var frame, out _) || frame.Station != Config.Station.Address || frame.IsReply)
        {
            return null;
        }

        // Steps 5-6. A READ whose descriptors, ATH'd just below the floor, would overlap their source clears the lists.
        if (ReadCount(frame) is { } n)
        {
            _lists.ClearIfReached(9 + (8 * n), 4 * n);
        }

        // DEFINE LIST: a defined id clears all lists, and its descriptors' ATH must fit below the floor, before the items.
        if (DefineHeader(frame) is { } header && _lists.PrepareDefine(header.List, header.Count) is var refused && refused != ProtocolError.None)
        {
            return Reply(frame, [(byte)refused]);
        }

        if (!RequestCodec.TryParse(frame, this, out var request, out var error))
        {
            return error == ProtocolError.None ? null : Reply(frame, [(byte)error]);
        }

        error = request switch
        {
            DefineListRequest define => _lists.Define(define),
            ReadListRequest list when !_lists.IsDefined(list.List) => ProtocolError.ListNotDefined,
            _ => ProtocolError.None,
        };
        if (error != ProtocolError.None)
        {
            return Reply(frame, [(byte)error]);
        }

        // Step 7: execute; the caller sends the reply after the configured delay. A reply (12 + 2P characters) that
        // would reach the floor, or a READ's descriptors below it, clears every list first.
        var payload = Execute(request);
        _lists.ClearIfReached(12 + (2 * payload.Length), request is ReadRequest read ? 4 * read.Items.Length : 0);
        return Reply(frame, [0, .. payload]);
    }

    /// <summary>LIST and COUNT of a DEFINE LIST whose COUNT, body length and LIST passed (step 6 up to the items).</summary>
    private static (int List, int Count)? DefineHeader(FreeportFrame frame) =>
        frame.Command == (byte)CommandCode.DefineList && frame.BodyBytes >= 6 && frame.Payload[1] is >= 1 and <= ProtocolLimits.MaxReadItems
            && frame.BodyBytes == 6 + (4 * frame.Payload[1]) && frame.Payload[0] is >= 1 and <= ProtocolLimits.MaxLists
            ? (frame.Payload[0], frame.Payload[1]) : null;

    /// <summary>COUNT of a READ whose COUNT and body length passed: the handler ATHs its descriptors now.</summary>
    private static int? ReadCount(FreeportFrame frame) =>
        frame.Command == (byte)CommandCode.Read && frame.BodyBytes >= 5 && frame.Payload[0] is >= 1 and <= ProtocolLimits.MaxReadItems
            && frame.BodyBytes == 5 + (4 * frame.Payload[0]) ? frame.Payload[0] : null;

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
            if ((area == ProtocolArea.SM && Config.IsProtectedSmByte(i)) || (area == ProtocolArea.V && Config.IsHandlerVByte(i)))
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
                return ReadItems(read.Items);
            case ReadListRequest list:
                return ReadItems(_lists.Items(list.List));
            case DefineListRequest:
                return [];
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

    private byte[] ReadItems(IEnumerable<ReadItem> items) =>
        [.. items.SelectMany(item => Memory.Area(item.Area).Skip(item.Offset).Take(item.Length))];

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
