using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Core.Transport;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>
/// The master's handshake played against scripted CPUs. The frames are the ones the captures in TestKit PpiCaptures show
/// (request FC 6C as libnodave and HslCommunication send it, acknowledge E5, polls 5C/7C), with our PDU reference 1.
/// </summary>
public sealed class PpiMasterTests
{
    private const string Request = "> 68 1B 1B 68 02 00 6C  32 01 00 00 00 01 00 0E 00 00  04 01 12 0A 10 02 00 0C 00 01 84 00 09 60  DD 16 // read VB300 x12";
    private const string Acknowledge = "< E5";
    private const string Poll5C = "> 10 02 00 5C 5E 16";
    private const string Poll7C = "> 10 02 00 7C 7E 16";
    private const string Answer = "< 68 21 21 68 00 02 08  32 03 00 00 00 01 00 02 00 10 00 00  04 01 FF 04 00 60 43 6C 99 B2 43 15 80 0B 43 33 66 76  E9 16";

    private static readonly S7Item Vb300 = S7Item.Bytes(S7Area.V, 300, 12);
    private static readonly Station Cpu = new(2);

    /// <summary>The captures here number the job 1; a real link starts at a random reference.</summary>
    private static readonly PpiMasterOptions FromOne = new() { FirstReference = 1 };

    [Fact]
    public async Task Read_FirstJob_CarriesTheLinksFirstReferenceAndTakesOnlyItsAnswer()
    {
        var transport = Script(
            "> 68 1B 1B 68 02 00 6C  32 01 00 00 26 58 00 0E 00 00  04 01 12 0A 10 02 00 0C 00 01 84 00 09 60  5A 16 // reference 16#2658",
            Acknowledge,
            Poll5C,
            "< 68 21 21 68 00 02 08  32 03 00 00 26 58 00 02 00 10 00 00  04 01 FF 04 00 60 43 6C 99 B2 43 15 80 0B 43 33 66 76  66 16");
        var master = new PpiMaster(transport, new PpiMasterOptions { FirstReference = 0x2658 });

        var results = await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        Hex.Format(results[0].Data.AsSpan()).Should().Be("43 6C 99 B2 43 15 80 0B 43 33 66 76");
        transport.AssertComplete();
    }

    [Fact]
    public void Options_EachLinkDrawsItsOwnFirstReference()
    {
        // An answer a killed run left in the CPU must not match the next run's first job: not every run starts at 1.
        var firsts = Enumerable.Range(0, 6).Select(_ => new PpiMasterOptions().FirstReference).ToList();

        firsts.Should().OnlyContain(r => r >= 1);
        firsts.Distinct().Should().HaveCountGreaterThan(1);
    }

    [Fact]
    public async Task Read_AcknowledgedThenPolled_ReturnsTheBytes()
    {
        var transport = Script(Request, Acknowledge, Poll5C, Answer);
        var master = new PpiMaster(transport, FromOne);

        var results = await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        Hex.Format(results[0].Data.AsSpan()).Should().Be("43 6C 99 B2 43 15 80 0B 43 33 66 76");
        master.Exchanges.Should().Be(1);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_CpuNotReadyForTwoPolls_TogglesTheFrameCountBitUntilTheAnswer()
    {
        var transport = Script(Request, Acknowledge, Poll5C, "< E5 // not yet: its scan has not reached the communication phase", Poll7C, "< E5", Poll5C, Answer);
        var master = new PpiMaster(transport, FromOne);

        await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        master.EmptyPolls.Should().Be(2);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_AcknowledgeLost_SendsTheSameRequestAgain()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(clock, Request, "< no response", Request, Acknowledge, Poll5C, Answer);
        var master = new PpiMaster(transport, FromOne, clock);

        await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        master.Repeats.Should().Be(1);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_AnswerToAPollLost_RepeatsThePollWithTheSameFrameCountBit()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(clock, Request, Acknowledge, Poll5C, "< no response", Poll5C, Answer);
        var master = new PpiMaster(transport, FromOne, clock);

        await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_NothingAnswers_FailsWithNoAnswerAfterThreeTries()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(clock, Request, "< no response", Request, "< no response", Request, "< no response");
        var master = new PpiMaster(transport, FromOne, clock);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.NoAnswer);
        failure.Station.Should().Be(Cpu);
        failure.Message.Should().Contain("even parity");
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_TokenFrameOnTheBus_FailsWithAnotherMaster()
    {
        var transport = Script(Request, "< DC 04 01 // station 1 passes the token to station 4");
        var master = new PpiMaster(transport, FromOne);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.AnotherMaster);
        failure.Message.Should().Contain("another master");
    }

    [Fact]
    public async Task Read_AnotherMastersRequestToOurCpu_FailsWithAnotherMaster()
    {
        var transport = Script(Request, "< 10 02 01 5C 5F 16 // station 1 polls our CPU");
        var master = new PpiMaster(transport, FromOne);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        (await act.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.AnotherMaster);
    }

    [Fact]
    public async Task Read_AdapterEchoesOurFrames_IgnoresTheEcho()
    {
        var transport = Script(
            Request, "< 68 1B 1B 68 02 00 6C 32 01 00 00 00 01 00 0E 00 00 04 01 12 0A 10 02 00 0C 00 01 84 00 09 60 DD 16 E5",
            Poll5C, "< 10 02 00 5C 5E 16", Answer);
        var master = new PpiMaster(transport, FromOne);

        var results = await master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        results[0].Succeeded.Should().BeTrue();
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_AnswerGarbledThreeTimes_FailsWithFrameCorrupt()
    {
        const string garbled = "< 68 21 21 68 00 02 08  32 03 00 00 00 01 00 02 00 10 00 00  04 01 FF 04 00 60 43 6C 99 B2 43 15 80 0B 43 33 66 76  E8 16";
        var transport = Script(Request, Acknowledge, Poll5C, garbled, Poll5C, garbled, Poll5C, garbled);
        var master = new PpiMaster(transport, FromOne);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.FrameCorrupt);
        failure.Message.Should().Contain("ChecksumMismatch");
        transport.AssertComplete();
    }

    [Fact]
    public async Task Read_JobRefused_FailsWithNegativeReplyNamingTheError()
    {
        var transport = Script(Request, Acknowledge, Poll5C, "< 68 0F 0F 68 00 02 08  32 02 00 00 00 01 00 00 00 00 85 00  C4 16");
        var master = new PpiMaster(transport, FromOne);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.NegativeReply);
        failure.Message.Should().Be("station 2 refused the read: error 16#8500 (incorrect PDU size: the length fields do not agree with the data)");
    }

    [Fact]
    public async Task Read_CpuNeverReady_FailsWithTimeoutAfterTheAnswerTime()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(clock, Request, Acknowledge, Poll5C, "< no response", Poll5C, "< E5");
        var master = new PpiMaster(transport, FromOne with { AnswerTimeout = TimeSpan.FromMilliseconds(50) }, clock);

        var act = () => master.ReadAsync(Cpu, [Vb300], CancellationToken.None);

        (await act.Should().ThrowAsync<PlcCommunicationException>()).Which.Kind.Should().Be(PlcErrorKind.Timeout);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Write_Bit_SendsABitItemAndReturnsItsCode()
    {
        var transport = Script(
            "> 68 20 20 68 02 00 6C  32 01 00 00 00 01 00 0E 00 05  05 01 12 0A 10 01 00 01 00 00 82 00 00 05  00 03 00 01 01  75 16 // Q0.5 := 1",
            Acknowledge, Poll5C,
            "< 68 12 12 68 00 02 08  32 03 00 00 00 01 00 02 00 01 00 00  05 01 FF  48 16");
        var master = new PpiMaster(transport, FromOne);
        PpiAddressing.TryWrite(PlcAddress.Parse("Q0.5"), 1, out var item, out _);

        var codes = await master.WriteAsync(Cpu, [item!], CancellationToken.None);

        codes.Should().Equal(S7ReturnCode.Success);
        transport.AssertComplete();
    }

    [Fact]
    public async Task Write_AnswerToAPollLost_RepeatsThePollNeverTheJob()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(
            clock,
            "> 68 20 20 68 02 00 6C  32 01 00 00 00 01 00 0E 00 05  05 01 12 0A 10 01 00 01 00 00 82 00 00 05  00 03 00 01 01  75 16 // Q0.5 := 1",
            Acknowledge, Poll5C, "< no response", Poll5C,
            "< 68 12 12 68 00 02 08  32 03 00 00 00 01 00 02 00 01 00 00  05 01 FF  48 16");
        var master = new PpiMaster(transport, FromOne, clock);
        PpiAddressing.TryWrite(PlcAddress.Parse("Q0.5"), 1, out var item, out _);

        var codes = await master.WriteAsync(Cpu, [item!], CancellationToken.None);

        codes.Should().Equal(S7ReturnCode.Success);
        master.Repeats.Should().Be(1, "the poll, with the same frame count bit: the CPU repeats its answer and writes nothing again");
        transport.AssertComplete();
    }

    [Fact]
    public async Task Write_NoAcknowledge_FailsWithoutSendingTheJobAgain()
    {
        var clock = new ManualTimeProvider();
        var transport = Script(
            clock,
            "> 68 20 20 68 02 00 6C  32 01 00 00 00 01 00 0E 00 05  05 01 12 0A 10 01 00 01 00 00 82 00 00 05  00 03 00 01 01  75 16 // Q0.5 := 1",
            "< no response");
        var master = new PpiMaster(transport, FromOne, clock);
        PpiAddressing.TryWrite(PlcAddress.Parse("Q0.5"), 1, out var item, out _);

        var act = () => master.WriteAsync(Cpu, [item!], CancellationToken.None);

        var failure = (await act.Should().ThrowAsync<PlcCommunicationException>()).Which;
        failure.Kind.Should().Be(PlcErrorKind.NoAnswer);
        failure.Message.Should().StartWith("station 2 did not answer the job (sent once)");
        master.Repeats.Should().Be(0);
        transport.AssertComplete();
    }

    private static ScriptedTransport Script(params string[] lines) => new(string.Join('\n', lines));

    private static ScriptedTransport Script(ManualTimeProvider clock, params string[] lines) => new(string.Join('\n', lines), clock);
}
