using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Writes;
using static OperatorPanel.Core.Tests.Polling.PollingSome;

namespace OperatorPanel.Core.Tests.Writes;

public sealed class WriteRequestTests
{
    [Theory]
    [InlineData("VW10", 1)]
    [InlineData("VD10", 2)]
    [InlineData("VB10", 2)]
    public void Bytes_DataNotTheAddressWidth_Throws(string address, int length)
    {
        var act = () => WriteRequest.Bytes(One, PlcAddress.Parse(address), [.. new byte[length]]);

        act.Should().Throw<ArgumentException>().WithParameterName("data");
    }

    [Fact]
    public void Bytes_BitAddress_Throws()
    {
        var act = () => WriteRequest.Bytes(One, PlcAddress.Parse("V1.0"), [0x01]);

        act.Should().Throw<ArgumentException>().WithParameterName("address");
    }

    [Fact]
    public void Bit_ByteAddress_Throws()
    {
        var act = () => WriteRequest.Bit(One, PlcAddress.Parse("VB1"), true);

        act.Should().Throw<ArgumentException>().WithParameterName("address");
    }

    [Fact]
    public void Value_Bit_IsOneByteZeroOrOne()
    {
        WriteRequest.Bit(One, PlcAddress.Parse("Q0.5"), true).Value.Should().Equal(0x01);
        WriteRequest.Bit(One, PlcAddress.Parse("Q0.5"), false).Value.Should().Equal(0x00);
    }

    [Fact]
    public void ToString_DoubleWord_PrintsS7Hex()
    {
        WriteRequest.Bytes(One, PlcAddress.Parse("VD4"), [0x00, 0x01, 0x86, 0xA0]).ToString().Should().Be("station 1 VD4 := 16#000186A0");
    }
}
