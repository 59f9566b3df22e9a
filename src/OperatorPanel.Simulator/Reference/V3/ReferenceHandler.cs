using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Simulator.Reference.V3;

/// <summary>
/// A plain model of an S7-200 running a protocol v3 handler, following docs/protocol.md section 4 step by step. The
/// generated STL must answer every message byte for byte as this does. Memory is shared with whatever drives the
/// process (tests, the demo); the handler's own V bytes hold nothing here (their content is not part of the protocol).
/// </summary>
public sealed partial class ReferenceHandler
{
    /// <summary>SMB6 holds the CPU type in bits 4-7 (seed 002 Table C-7); SMW22-SMW26 the scan times (Table C-9).</summary>
    private const int Smb6 = 6, Smw22 = 22;

    private OperatingMode _mode = OperatingMode.Run;
    private ModeSwitch _switch = ModeSwitch.Run;

    public ReferenceHandler(HandlerSetup setup)
    {
        ArgumentNullException.ThrowIfNull(setup);
        Setup = setup;
        Memory = new PlcMemory(setup.Cpu);
        Memory.SM[Smb6] = setup.Cpu.CpuIdCode;
        Memory.SetBit(ProtocolArea.SM, 0, 7, true);
        List = new StationList();
    }

    public HandlerSetup Setup { get; }

    public PlcMemory Memory { get; }

    public StationList List { get; }

    /// <summary>STOP hands the port to PPI and forgets the list.</summary>
    public OperatingMode Mode
    {
        get => _mode;
        set
        {
            _mode = value;
            List.Clear();
        }
    }

    /// <summary>The mode switch; SM0.7 follows it. Either change forgets the list (the handler sets the port up again).</summary>
    public ModeSwitch Switch
    {
        get => _switch;
        set
        {
            _switch = value;
            List.Clear();
            Memory.SetBit(ProtocolArea.SM, 0, 7, value == ModeSwitch.Run);
        }
    }

    /// <summary>
    /// A message as RCV hands it over: every byte from '&lt;' until SMW92 ms passed without a character (or SMB94 bytes
    /// arrived); <paramref name="received"/> false when the receive ended otherwise (a parity or framing error). The
    /// reply to send, or null for silence. After the reply to STOP the CPU is in STOP.
    /// </summary>
    public byte[]? HandleMessage(ReadOnlySpan<byte> message, bool received = true)
    {
        if (Mode == OperatingMode.Stop || Switch != ModeSwitch.Run || !received)
        {
            return null;
        }

        // Step 1, the receive interrupt: a message of LEN bytes (LEN at least 8) for this station; else receive again.
        if (message.Length < Limits.RequestBytes(0) || message.Length > Setup.Shape.RequestBytes || message[0] != Limits.Start
            || message[1] != message.Length || message[2] != Setup.Station.Address)
        {
            return null;
        }

        // Step 2: the check.
        if (!WordCheck.Matches(message))
        {
            return null;
        }

        var check = Codec.RequestCheckOf(message);
        var command = (Command)(message[3] & 0x0F);
        var payload = message[Limits.RequestHead..^WordCheck.Bytes];
        var (status, data) = Answer(command, payload);
        var reply = Codec.Encode(new Reply(status, check, data));
        if (command == Command.Stop && status == ReplyStatus.Ok)
        {
            Mode = OperatingMode.Stop;
        }

        return reply;
    }

    /// <summary>Records one finished scan of <paramref name="milliseconds"/> in SMW22/SMW24/SMW26.</summary>
    public void CompleteScan(ushort milliseconds, bool first)
    {
        var min = Memory.ReadWord(ProtocolArea.SM, Smw22 + 2);
        var max = Memory.ReadWord(ProtocolArea.SM, Smw22 + 4);
        Memory.WriteWord(ProtocolArea.SM, Smw22, milliseconds);
        Memory.WriteWord(ProtocolArea.SM, Smw22 + 2, first ? milliseconds : Math.Min(min, milliseconds));
        Memory.WriteWord(ProtocolArea.SM, Smw22 + 4, first ? milliseconds : Math.Max(max, milliseconds));
    }

    private ImmutableArray<byte> Identify()
    {
        var flags = Memory.GetBit(ProtocolArea.SM, 0, 7) ? Identity.ModeSwitchRunFlag : (byte)0;
        return Setup.IdentityWith(
            Memory.SM[Smb6], flags, Memory.ReadWord(ProtocolArea.SM, Smw22), Memory.ReadWord(ProtocolArea.SM, Smw22 + 2),
            Memory.ReadWord(ProtocolArea.SM, Smw22 + 4)).ToPayload();
    }
}
