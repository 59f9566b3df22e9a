using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>
/// The PPI bus's link: it opens its port, keeps off a bus another master uses, sends writes once, and numbers every job
/// on its port from one sequence of PDU references.
/// </summary>
public sealed class PpiLinkTests
{
    private const string Request = "> 68 1B 1B 68 02 00 6C  32 01 00 00 00 01 00 0E 00 00  04 01 12 0A 10 02 00 0C 00 01 84 00 09 60  DD 16 // read VB300 x12";
    private const string ReadAnswer = "< 68 21 21 68 00 02 08  32 03 00 00 00 01 00 02 00 10 00 00  04 01 FF 04 00 60 43 6C 99 B2 43 15 80 0B 43 33 66 76  E9 16 // reference 1";
    private const string Poll5C = "> 10 02 00 5C 5E 16";
    private static readonly S7Item Vb300 = S7Item.Bytes(S7Area.V, 300, 12);
    private static readonly Station Cpu = new(2);

    [Fact]
    public async Task Read_AnotherMasterSeen_KeepsOffTheBusForTheRestAndSaysWhy()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport(string.Join('\n', Request, "< DC 04 01 // station 1 passes the token to station 4"), clock);
        var link = new PpiLink(transport, PpiMasterOptions.ForBaud(9600) with { FirstReference = 1 }, clock);

        var first = () => link.ReadAsync(Cpu, [Vb300], default);
        (await first.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.AnotherMaster);
        clock.Advance(TimeSpan.FromSeconds(5));
        var second = () => link.ReadAsync(Cpu, [Vb300], default);

        var kept = (await second.Should().ThrowAsync<PlcCommunicationException>()).Which;
        kept.Kind.Should().Be(PlcErrorKind.AnotherMaster);
        kept.Message.Should().Contain("keeps off");
        link.Problem.Should().StartWith("another master on the bus");
        transport.Written.Should().HaveCount(1, "nothing is sent while the link keeps off the bus");
    }

    [Fact]
    public async Task Write_NoAcknowledge_SentOnceNeverRepeated()
    {
        var clock = new ManualTimeProvider();
        var write = "> 68 20 20 68 02 00 6C  32 01 00 00 00 01 00 0E 00 05  05 01 12 0A 10 02 00 01 00 00 83 00 00 20  00 04 00 08 2A  C3 16 // write MB4 := 2A (FCS = sum of DA..data mod 256)";
        var transport = new ScriptedTransport(string.Join('\n', write, "< no response"), clock);
        var link = new PpiLink(transport, PpiMasterOptions.ForBaud(9600) with { FirstReference = 1 }, clock);

        var act = () => link.WriteAsync(Cpu, [S7WriteItem.Of(S7Item.Bytes(S7Area.M, 4, 1), [0x2A])], default);

        (await act.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.NoAnswer);
        transport.Written.Should().HaveCount(1);
    }

    [Fact]
    public async Task Write_AfterARead_TakesTheNextReferenceAndRefusesALateAnswerToTheRead()
    {
        var clock = new ManualTimeProvider();
        var transport = new ScriptedTransport(string.Join('\n',
            Request, "< E5", Poll5C, ReadAnswer,
            "> 68 20 20 68 02 00 6C  32 01 00 00 00 02 00 0E 00 05  05 01 12 0A 10 02 00 01 00 00 83 00 00 20  00 04 00 08 2A  C4 16 // write MB4 := 2A, reference 2",
            "< E5", Poll5C, ReadAnswer + ", the read's answer again: late, or repeated by a CPU"), clock);
        var link = new PpiLink(transport, PpiMasterOptions.ForBaud(9600) with { FirstReference = 1 }, clock);
        await link.ReadAsync(Cpu, [Vb300], default);

        var act = () => link.WriteAsync(Cpu, [S7WriteItem.Of(S7Item.Bytes(S7Area.M, 4, 1), [0x2A])], default);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.FrameCorrupt);
        failure.Message.Should().Be("station 2 answered the write with an unusable PDU: ReferenceMismatch");
        transport.AssertComplete();
    }
}
