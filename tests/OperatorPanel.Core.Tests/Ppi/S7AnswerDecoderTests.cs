using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>Captured answers (TestKit PpiCaptures) read by <see cref="S7AnswerDecoder"/>, and answers that must be refused.</summary>
public sealed class S7AnswerDecoderTests
{
    [Fact]
    public void TryRead_CapturedTwelveBytes_GivesTheBytes()
    {
        var error = S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadVb300Answer), 0x2658, [S7Item.Bytes(S7Area.V, 300, 12)], out _, out var results);

        error.Should().Be(S7PduError.None);
        Hex.Format(results[0].Data.AsSpan()).Should().Be("43 6C 99 B2 43 15 80 0B 43 33 66 76");
    }

    [Fact]
    public void TryRead_CapturedSevenItemsWithPadding_GivesEachItemItsBytes()
    {
        S7Item[] items =
        [
            S7Item.Bytes(S7Area.I, 0, 2), S7Item.Bytes(S7Area.Q, 0, 1), S7Item.Bytes(S7Area.M, 0, 1), S7Item.Bytes(S7Area.M, 10, 1),
            S7Item.Bytes(S7Area.V, 100, 1), S7Item.Bytes(S7Area.V, 110, 1), S7Item.Bytes(S7Area.V, 200, 4),
        ];

        var error = S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadSevenItemsAnswer), 0x2659, items, out _, out var results);

        error.Should().Be(S7PduError.None);
        results.Select(r => Hex.Format(r.Data.AsSpan())).Should().Equal("00 00", "09", "00", "00", "00", "00", "00 47 00 6E");
    }

    [Fact]
    public void TryRead_CapturedBitAnswer_GivesOneByte()
    {
        var error = S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadQ01Answer), 0, [S7Item.Bit(S7Area.Q, 0, 1)], out _, out var results);

        error.Should().Be(S7PduError.None);
        results[0].Should().Match<S7ItemResult>(r => r.DataSize == S7DataSize.Bit && r.Data.Length == 1 && r.Data[0] == 1);
    }

    [Fact]
    public void TryRead_CapturedTimers_GivesFiveBytesPerTimer()
    {
        var error = S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadTimersAnswer), 0, [S7Item.Timers(32, 3)], out _, out var results);

        error.Should().Be(S7PduError.None);
        Hex.Format(results[0].Data.AsSpan(0, 5)).Should().Be("02 00 00 7F FF");
        results[0].DataSize.Should().Be(S7DataSize.OctetString);
    }

    [Fact]
    public void TryWrite_CapturedAnswer_GivesSuccess()
    {
        var error = S7AnswerDecoder.TryWrite(PpiCaptures.Pdu(PpiCaptures.WriteVd300Answer), 0x2734, 1, out _, out var codes);

        error.Should().Be(S7PduError.None);
        codes.Should().Equal(S7ReturnCode.Success);
    }

    [Fact]
    public void TryControl_CapturedStopAnswer_IsAccepted()
    {
        S7AnswerDecoder.TryControl(PpiCaptures.Pdu(PpiCaptures.StopAnswer), 0, S7Function.PlcStop, out _).Should().Be(S7PduError.None);
    }

    [Fact]
    public void TryRead_AnswerToAnOlderJob_IsAReferenceMismatch()
    {
        S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadVb300Answer), 0x2659, [S7Item.Bytes(S7Area.V, 300, 12)], out _, out _)
            .Should().Be(S7PduError.ReferenceMismatch);
    }

    [Fact]
    public void TryRead_ItemOfAnotherLength_IsABadItem()
    {
        S7AnswerDecoder.TryRead(PpiCaptures.Pdu(PpiCaptures.ReadVb300Answer), 0x2658, [S7Item.Bytes(S7Area.V, 300, 10)], out _, out _)
            .Should().Be(S7PduError.BadItem);
    }

    [Fact]
    public void TryRead_Refusal_IsRefusedWithItsErrorClassAndCode()
    {
        var error = S7AnswerDecoder.TryRead(S7AnswerCodec.Refusal(9, 0x85, 0x00), 9, [S7Item.Bytes(S7Area.V, 0, 1)], out var header, out _);

        error.Should().Be(S7PduError.Refused);
        header.Error.Should().Be(0x8500);
        S7ErrorText.Describe(header.Error).Should().Contain("PDU size");
    }

    [Fact]
    public void TryRead_ItemErrorCode_IsAFailedResultNotAPduError()
    {
        var answer = S7AnswerCodec.Read(3, [S7ItemResult.Failed(S7ReturnCode.AddressOutOfRange), S7ItemResult.Of(S7DataSize.Bits, [0x12])]);

        var error = S7AnswerDecoder.TryRead(answer, 3, [S7Item.Bytes(S7Area.V, 9000, 1), S7Item.Bytes(S7Area.M, 0, 1)], out _, out var results);

        error.Should().Be(S7PduError.None);
        results.Select(r => r.Code).Should().Equal(S7ReturnCode.AddressOutOfRange, S7ReturnCode.Success);
        results[1].Data.Should().Equal((byte)0x12);
    }

    [Fact]
    public void TryRead_TruncatedPdu_IsTooShort()
    {
        var pdu = PpiCaptures.Pdu(PpiCaptures.ReadVb300Answer);

        S7AnswerDecoder.TryRead(pdu.AsSpan(0, pdu.Length - 3), 0x2658, [S7Item.Bytes(S7Area.V, 300, 12)], out _, out _)
            .Should().Be(S7PduError.TooShort);
    }
}
