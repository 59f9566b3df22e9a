using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Simulator.Stl.Ppi;
using OperatorPanel.Simulator.Tests.Hosting;
using OperatorPanel.TestKit;

namespace OperatorPanel.Simulator.Tests.Stl.Ppi;

/// <summary>
/// The CPU's PPI station fed with telegrams as published captures show them (TestKit PpiCaptures): its answers must be
/// those captures byte for byte, because masters this project did not write will drive it.
/// </summary>
public sealed class PpiSlaveTests
{
    private readonly FakePpiMemory _memory = new();
    private readonly PpiSlave _slave = new(new PpiSettings());

    [Fact]
    public void Receive_CapturedSevenItemRead_AcknowledgesThenAnswersTheCapturedBytesAfterTheCommunicationPhase()
    {
        _memory.Areas[S7Area.Q][0] = 0x09;
        _memory.Areas[S7Area.V].AsSpan(200).SetBytes([0x00, 0x47, 0x00, 0x6E]);

        Reply(PpiCaptures.ReadSevenItemsRequest).Should().Be("E5");
        Reply(PpiCaptures.Poll).Should().Be("E5", "no communication phase yet: the job waits for the scan");
        _slave.Serve(_memory);

        Reply("10 02 00 7C 7E 16").Should().Be(Hex.Format(Hex.Parse(PpiCaptures.ReadSevenItemsAnswer)));
    }

    [Fact]
    public void Receive_CapturedWrite_WritesInTheCommunicationPhaseAndAnswersTheCapturedBytes()
    {
        Reply(PpiCaptures.WriteVd300Request).Should().Be("E5");
        _memory.Areas[S7Area.V][300].Should().Be(0, "nothing is done before the communication phase");

        _slave.Serve(_memory);

        Hex.Format(_memory.Areas[S7Area.V].AsSpan(300, 4)).Should().Be("45 20 80 00");
        Reply(PpiCaptures.Poll).Should().Be(PpiCaptures.WriteVd300Answer);
    }

    [Fact]
    public void Receive_PollRepeatedWithTheSameFrameCountBit_RepeatsTheLastAnswerWithoutDoingTheJobAgain()
    {
        Reply(PpiCaptures.ReadVb300Request);
        _slave.Serve(_memory);
        var answer = Reply(PpiCaptures.Poll);

        var repeated = Reply(PpiCaptures.Poll);

        repeated.Should().Be(answer);
        _memory.Reads.Should().Be(1);
        Reply("10 02 00 7C 7E 16").Should().Be("E5", "a toggled frame count bit is a new poll, and there is nothing left to fetch");
    }

    [Fact]
    public void Receive_RequestWithFrameCountNotValid_IsAlwaysANewJob()
    {
        var request = PpiFrameCodec.Encode(PpiFrame.Variable(2, 0, PpiFunctionCode.FirstRequest, S7JobCodec.Stop(1)));

        Reply(Hex.Format(request)).Should().Be("E5");
        Reply(Hex.Format(request)).Should().Be("E5");
        _slave.Serve(_memory);

        _memory.Controls.Should().Equal(S7Function.PlcStop);
    }

    [Fact]
    public void Receive_TelegramForAnotherStation_IsIgnored()
    {
        _slave.Receive(PpiFrame.Fixed(3, 0, PpiFunctionCode.Poll(false))).Should().BeNull();
        _slave.Receive(PpiFrame.Token(2, 1)).Should().BeNull();
        _slave.Receive(PpiFrame.Fixed(2, 0, 0x49)).Should().BeNull("FDL status requests are not answered (unsupported)");
    }

    [Fact]
    public void Receive_TwoMasters_KeepTheirOwnJobs()
    {
        _memory.Areas[S7Area.M][0] = 0x11;
        _memory.Areas[S7Area.M][1] = 0x22;
        _slave.Receive(Request(master: 0, S7JobCodec.Read(1, [S7Item.Bytes(S7Area.M, 0, 1)])));
        _slave.Receive(Request(master: 1, S7JobCodec.Read(1, [S7Item.Bytes(S7Area.M, 1, 1)])));
        _slave.Serve(_memory);

        var toZero = _slave.Receive(PpiFrame.Fixed(2, 0, PpiFunctionCode.Poll(false)))!;
        var toOne = _slave.Receive(PpiFrame.Fixed(2, 1, PpiFunctionCode.Poll(false)))!;

        (toZero.Destination, toZero.Data[^1]).Should().Be(((byte)0, (byte)0x11));
        (toOne.Destination, toOne.Data[^1]).Should().Be(((byte)1, (byte)0x22));
    }

    [Fact]
    public void Receive_JobLargerThanThePdu_IsRefusedWith8500()
    {
        var slave = new PpiSlave(new PpiSettings { PduSize = 64 });
        var items = Enumerable.Range(0, 5).Select(i => S7Item.Bytes(S7Area.V, i * 20, 1)).ToArray();
        slave.Receive(Request(0, S7JobCodec.Read(7, items))).Should().Be(PpiFrame.ShortAcknowledge);
        slave.Serve(_memory);

        var answer = slave.Receive(PpiFrame.Fixed(2, 0, PpiFunctionCode.Poll(false)))!;

        S7Header.TryRead(answer.Data.AsSpan(), out var header, out _).Should().BeTrue();
        (header.Type, header.Reference, header.Error).Should().Be((S7MessageType.Ack, (ushort)7, 0x8500));
    }

    [Fact]
    public void Receive_SetupCommunicationOffering960_AgreesTo240()
    {
        _slave.Receive(Request(0, S7JobCodec.SetupCommunication(3, 960)));
        _slave.Serve(_memory);

        var answer = _slave.Receive(PpiFrame.Fixed(2, 0, PpiFunctionCode.Poll(false)))!;

        S7AnswerDecoder.TrySetupCommunication(answer.Data.AsSpan(), 3, out _, out var size).Should().Be(S7PduError.None);
        size.Should().Be(240);
    }

    private static PpiFrame Request(byte master, byte[] job) => PpiFrame.Variable(2, master, PpiFunctionCode.FirstRequest, job);

    /// <summary>The slave's reaction to a telegram given as hex, as hex ("" for none).</summary>
    private string Reply(string telegram) =>
        _slave.Receive(PpiCaptures.Frame(telegram)) is { } reply ? Hex.Format(PpiFrameCodec.Encode(reply)) : "";
}
