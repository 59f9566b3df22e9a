using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Emit;

/// <summary>
/// Fragments of the technician notes that change with the options (the whole text for CPU 224 station 2 is a golden
/// file): the port's SM bytes and events, the PC/PPI cable's baud switches, the station number the project must carry.
/// </summary>
public sealed class TechnicianNotesTests
{
    [Fact]
    public void Write_Port1At19200_NamesSmb130Smb186To194AndThePort1Events()
    {
        var notes = Lines(HandlerGoldenTests.Cpu226Port1Station17);

        notes.Should().Contain("  Port         port 1: SMB130, SMB186-SMB194; timed interrupt 0 (SMB34)");
        notes.Should().Contain("  - Your program leaves SMB130, SMB186-SMB194, SMB34, events 24, 10, 26 and the V range above alone.");
        notes.Should().Contain("     port settings (PPI address, baud rate) apply only while the port speaks PPI; the handler sets SMB130 itself.");
    }

    [Fact]
    public void Write_Protocol3Full_NoTimedInterruptRefusal83AndTheEndTimer()
    {
        var notes = Lines(HandlerGoldenTests.Cpu224Port0Station2 with { Protocol = 3 });

        notes.Should().Contain("  Port         port 0: SMB30, SMB86-SMB94 (no timed interrupt: SMB34 stays yours)");
        notes.Should().Contain("  - Your program leaves SMB30, SMB86-SMB94, events 23, 9 and the V range above alone.");
        notes.Should().Contain(l => l.Contains("the list's slots and its copy", StringComparison.Ordinal));
        notes.Should().Contain("               the panel cannot write there either (refused, 83). --merge checks an exported program for these");
        notes.Should().Contain("  A request ends 4 ms after its last character (the receive's inter-character timer, SMW92); the receive");
        notes.Should().NotContain(l => l.Contains("READ CHANGES", StringComparison.Ordinal) || l.Contains("CRC", StringComparison.Ordinal) || l.Contains("The compact handler", StringComparison.Ordinal));
        notes.Should().Contain(l => l.Contains("use the compact handler (the wizard", StringComparison.Ordinal), "the size warning offers it first");
    }

    [Fact]
    public void Write_Compact_SaysWhatItLeavesOutAndThatStopIsNotInIt()
    {
        var notes = Lines(HandlerGoldenTests.Cpu224Port0Station2 with { Protocol = 3, Compact = true });

        notes.Should().Contain("The compact handler");
        notes.Should().Contain("  It answers IDENTIFY, READ, WRITE and WRITE BITS only, to fit a small CPU. It leaves out the list (DEFINE");
        notes.Should().Contain("  STOP from the panel is not in the compact handler.");
        notes.Should().NotContain(l => l.Contains("list's slots", StringComparison.Ordinal));
        notes.Should().Contain("  around, and leaves whole, without pauses, once its check is computed (compact handler). A long scan of");
        notes.Should().NotContain(l => l.Contains("leaves in parts", StringComparison.Ordinal));
    }

    [Fact]
    public void Write_FullV3_SaysTheReplyMayPauseBetweenCharacters()
    {
        var notes = Lines(HandlerGoldenTests.Cpu224Port0Station2 with { Protocol = 3 });

        notes.Should().Contain("  around, and leaves in parts while its check is computed: it may pause a few scans of your program");
    }

    [Theory]
    [InlineData(9600, "  Older PC/PPI cable (6ES7 901-3BF20-0XA0): baud switches 1-3 at 010 (1 = up) for 9600 baud.")]
    [InlineData(19200, "  Older PC/PPI cable (6ES7 901-3BF20-0XA0): baud switches 1-3 at 001 (1 = up) for 19200 baud.")]
    [InlineData(38400, "  Older PC/PPI cable (6ES7 901-3BF20-0XA0): baud switches 1-3 at 000 (1 = up) for 38400 baud.")]
    [InlineData(57600, "  The older PC/PPI cable (6ES7 901-3BF20-0XA0) has no setting for 57600 baud: use another cable.")]
    public void Write_BaudRate_GivesTheOldPcPpiCableSwitchesOfSeed002TableA8(int baud, string line)
    {
        var notes = Lines(HandlerGoldenTests.Cpu224Port0Station2 with { BaudRate = baud });

        notes.Should().Contain(line);
    }

    [Fact]
    public void Write_Station17_TellsWhereTheStationNumberLivesAndWhatTheProjectMustSay()
    {
        var notes = Lines(HandlerGoldenTests.Cpu226Port1Station17);

        notes.Should().Contain("The panel's project must say the same for this PLC: station 17, CPU 226, 19200 baud.");
        notes.Should().Contain("     The panel's station number 17 is in the handler, not the PPI address of the system block.");
        notes.Should().Contain("When the panel gets no answer (opanel identify --device PORT --station 17 asks the handler)");
    }

    private static string[] Lines(HandlerOptions options)
    {
        var result = HandlerGenerator.Generate(options);
        result.Diagnostics.Should().BeEmpty();
        return result.TechnicianText.Split("\r\n");
    }
}
