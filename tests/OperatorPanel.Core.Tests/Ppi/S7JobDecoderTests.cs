using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>Captured jobs (TestKit PpiCaptures) as the CPU side reads them.</summary>
public sealed class S7JobDecoderTests
{
    [Fact]
    public void TryDecode_CapturedSevenItemRead_GivesTheItems()
    {
        S7JobDecoder.TryDecode(PpiCaptures.Pdu(PpiCaptures.ReadSevenItemsRequest), out var job, out var error).Should().BeTrue();

        error.Should().Be(S7PduError.None);
        var read = job.Should().BeOfType<S7Job.Read>().Subject;
        read.Reference.Should().Be(0x2659);
        read.Items.Select(i => $"{i.Area} {i.DataBlock} {i.ByteOffset} {i.DataLength}").Should().Equal(
            "I 0 0 2", "Q 0 0 1", "M 0 0 1", "M 0 10 1", "V 1 100 1", "V 1 110 1", "V 1 200 4");
    }

    [Fact]
    public void TryDecode_CapturedWrite_GivesItemAndValue()
    {
        S7JobDecoder.TryDecode(PpiCaptures.Pdu(PpiCaptures.WriteVd300Request), out var job, out _).Should().BeTrue();

        var write = job.Should().BeOfType<S7Job.Write>().Subject;
        write.Items.Should().ContainSingle();
        write.Items[0].Item.Should().Be(S7Item.Bytes(S7Area.V, 300, 4));
        Hex.Format(write.Items[0].Data.AsSpan()).Should().Be("45 20 80 00");
        write.Problems.Should().Equal(S7ReturnCode.Success);
    }

    [Fact]
    public void TryDecode_WriteOfTwoItemsWithPadding_RoundTrips()
    {
        S7WriteItem[] items =
        [
            S7WriteItem.Of(S7Item.Bytes(S7Area.Q, 0, 1), [0xA5]),
            S7WriteItem.Of(S7Item.Bit(S7Area.M, 3, 4), [0x01]),
            S7WriteItem.Of(S7Item.Words(S7Area.AQ, 2, 1), [0x12, 0x34]),
        ];

        S7JobDecoder.TryDecode(S7JobCodec.Write(5, items), out var job, out _).Should().BeTrue();

        var write = (S7Job.Write)job;
        write.Items.Select(i => (i.Item, Hex.Format(i.Data.AsSpan()))).Should().Equal(items.Select(i => (i.Item, Hex.Format(i.Data.AsSpan()))));
    }

    [Fact]
    public void TryDecode_WriteDataOfTheWrongLength_MarksTheItemInconsistent()
    {
        // VB0, 2 bytes asked, but the data item carries 8 bits.
        var pdu = Hex.Parse("32 01 00 00 00 01 00 0E 00 05  05 01 12 0A 10 02 00 02 00 01 84 00 00 00  00 04 00 08 7F");

        S7JobDecoder.TryDecode(pdu, out var job, out _).Should().BeTrue();

        ((S7Job.Write)job).Problems.Should().Equal(S7ReturnCode.DataTypeInconsistent);
    }

    [Theory]
    [InlineData(PpiCaptures.StopRequest, S7Function.PlcStop)]
    [InlineData(PpiCaptures.RunRequest, S7Function.PlcControl)]
    public void TryDecode_CapturedStopAndRun_AreControlJobs(string telegram, S7Function function)
    {
        S7JobDecoder.TryDecode(PpiCaptures.Pdu(telegram), out var job, out _).Should().BeTrue();

        job.Should().Be(new S7Job.Control(0, function));
    }

    [Fact]
    public void TryDecode_Setup_GivesTheOfferedSize()
    {
        S7JobDecoder.TryDecode(S7JobCodec.SetupCommunication(4, 960), out var job, out _).Should().BeTrue();

        job.Should().Be(new S7Job.SetupCommunication(4, 960));
    }

    [Fact]
    public void TryDecode_ItemCountThatDisagreesWithTheParameters_IsABadItem()
    {
        var pdu = S7JobCodec.Read(1, [S7Item.Bytes(S7Area.M, 0, 1)]);
        pdu[11] = 2;

        S7JobDecoder.TryDecode(pdu, out _, out var error).Should().BeFalse();
        error.Should().Be(S7PduError.BadItem);
    }

    [Fact]
    public void TryDecode_AnAnswer_IsNotAJob()
    {
        S7JobDecoder.TryDecode(S7AnswerCodec.Write(1, [S7ReturnCode.Success]), out _, out var error).Should().BeFalse();
        error.Should().Be(S7PduError.WrongMessageType);
    }
}
