using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

/// <summary>Answers the CPU side writes (the simulator's) against published captures, byte for byte.</summary>
public sealed class S7AnswerCodecTests
{
    [Fact]
    public void Read_SevenResultsOfTheCapture_IsTheCapturedAnswer()
    {
        S7ItemResult[] results =
        [
            Bytes(0x00, 0x00), Bytes(0x09), Bytes(0x00), Bytes(0x00), Bytes(0x00), Bytes(0x00), Bytes(0x00, 0x47, 0x00, 0x6E),
        ];

        Hex.Format(Frame(S7AnswerCodec.Read(0x2659, results))).Should().Be(Hex.Format(Hex.Parse(PpiCaptures.ReadSevenItemsAnswer)));
    }

    [Fact]
    public void Write_Success_IsTheCapturedAnswer()
    {
        Hex.Format(Frame(S7AnswerCodec.Write(0x2734, [S7ReturnCode.Success]))).Should().Be(PpiCaptures.WriteVd300Answer);
    }

    [Fact]
    public void Read_Bit_IsTheCapturedAnswer()
    {
        Hex.Format(Frame(S7AnswerCodec.Read(0, [S7ItemResult.Of(S7DataSize.Bit, [0x01])]))).Should().Be(PpiCaptures.ReadQ01Answer);
    }

    [Fact]
    public void Control_Stop_IsTheCapturedAnswer()
    {
        Hex.Format(Frame(S7AnswerCodec.Control(0, S7Function.PlcStop))).Should().Be(PpiCaptures.StopAnswer);
    }

    [Fact]
    public void ReadAnswerLength_CountsPaddingOfAllButTheLastItem()
    {
        S7Item[] items = [S7Item.Bytes(S7Area.M, 0, 1), S7Item.Bytes(S7Area.V, 0, 3)];

        S7AnswerCodec.ReadAnswerLength(items).Should().Be(12 + 2 + (4 + 1 + 1) + (4 + 3));
        S7AnswerCodec.Read(1, [Bytes(1), Bytes(1, 2, 3)]).Length.Should().Be(S7AnswerCodec.ReadAnswerLength(items));
    }

    private static S7ItemResult Bytes(params byte[] data) => S7ItemResult.Of(S7DataSize.Bits, data);

    private static byte[] Frame(byte[] answer) => PpiFrameCodec.Encode(PpiFrame.Variable(0, 2, PpiFunctionCode.ResponseDataLow, answer));
}
