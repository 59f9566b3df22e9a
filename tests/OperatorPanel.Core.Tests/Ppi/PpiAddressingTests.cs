using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Ppi;

public sealed class PpiAddressingTests
{
    [Theory]
    [InlineData("I0.3", "12 0A 10 02 00 01 00 00 81 00 00 00")]
    [InlineData("QB1", "12 0A 10 02 00 01 00 00 82 00 00 08")]
    [InlineData("MW4", "12 0A 10 02 00 02 00 00 83 00 00 20")]
    [InlineData("VD300", "12 0A 10 02 00 04 00 01 84 00 09 60")]
    [InlineData("SMB6", "12 0A 10 02 00 01 00 00 05 00 00 30")]
    [InlineData("SB2", "12 0A 10 02 00 01 00 00 04 00 00 10")]
    [InlineData("AIW4", "12 0A 10 04 00 01 00 00 06 00 00 20")]
    [InlineData("AQW0", "12 0A 10 04 00 01 00 00 07 00 00 00")]
    public void TryRead_EveryArea_GivesTheItemAddress(string address, string expected)
    {
        PpiAddressing.TryRead(PlcAddress.Parse(address), out var item, out var error).Should().BeTrue(error);

        Hex.Format(S7JobCodec.Read(0, [item]).AsSpan(12)).Should().Be(expected);
    }

    [Fact]
    public void TryRead_LocalMemory_IsRefusedWithAReason()
    {
        PpiAddressing.TryRead(PlcAddress.ForBytes(MemoryArea.L, 0, AccessWidth.Byte), out _, out var error).Should().BeFalse();

        error.Should().Be("L memory cannot be reached over PPI");
    }

    [Fact]
    public void TryWrite_Bit_IsABitItemWithOneByte()
    {
        PpiAddressing.TryWrite(PlcAddress.Parse("Q0.5"), 1, out var item, out _).Should().BeTrue();

        item!.Item.Should().Be(S7Item.Bit(S7Area.Q, 0, 5));
        item.Data.Should().Equal((byte)1);
        item.DataSize.Should().Be(S7DataSize.Bit);
    }

    [Fact]
    public void TryWrite_DoubleWord_IsBigEndian()
    {
        PpiAddressing.TryWrite(PlcAddress.Parse("VD100"), 0x12345678, out var item, out _).Should().BeTrue();

        Hex.Format(item!.Data.AsSpan()).Should().Be("12 34 56 78");
        item.Item.Should().Be(S7Item.Bytes(S7Area.V, 100, 4));
    }

    [Fact]
    public void TryWrite_AnalogOutputWord_IsAWordItem()
    {
        PpiAddressing.TryWrite(PlcAddress.Parse("AQW2"), 0x7D00, out var item, out _).Should().BeTrue();

        item!.Item.Should().Be(S7Item.Words(S7Area.AQ, 2, 1));
        Hex.Format(item.Data.AsSpan()).Should().Be("7D 00");
    }
}
