using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Tests.Addressing;

public sealed class PlcAddressTests
{
    [Theory]
    [InlineData("I0.3", MemoryArea.I, 0, 3, AccessWidth.Bit, "I0.3")]
    [InlineData("q1.7", MemoryArea.Q, 1, 7, AccessWidth.Bit, "Q1.7")]
    [InlineData("M10.3", MemoryArea.M, 10, 3, AccessWidth.Bit, "M10.3")]
    [InlineData("V100.7", MemoryArea.V, 100, 7, AccessWidth.Bit, "V100.7")]
    [InlineData("sm0.7", MemoryArea.SM, 0, 7, AccessWidth.Bit, "SM0.7")]
    [InlineData("S31.0", MemoryArea.S, 31, 0, AccessWidth.Bit, "S31.0")]
    [InlineData("IB0", MemoryArea.I, 0, null, AccessWidth.Byte, "IB0")]
    [InlineData("qb0", MemoryArea.Q, 0, null, AccessWidth.Byte, "QB0")]
    [InlineData("MB5", MemoryArea.M, 5, null, AccessWidth.Byte, "MB5")]
    [InlineData("VB100", MemoryArea.V, 100, null, AccessWidth.Byte, "VB100")]
    [InlineData("SMB30", MemoryArea.SM, 30, null, AccessWidth.Byte, "SMB30")]
    [InlineData("SB2", MemoryArea.S, 2, null, AccessWidth.Byte, "SB2")]
    [InlineData("IW0", MemoryArea.I, 0, null, AccessWidth.Word, "IW0")]
    [InlineData("QW0", MemoryArea.Q, 0, null, AccessWidth.Word, "QW0")]
    [InlineData("MW4", MemoryArea.M, 4, null, AccessWidth.Word, "MW4")]
    [InlineData("vw200", MemoryArea.V, 200, null, AccessWidth.Word, "VW200")]
    [InlineData("SMW22", MemoryArea.SM, 22, null, AccessWidth.Word, "SMW22")]
    [InlineData("aiw0", MemoryArea.AI, 0, null, AccessWidth.Word, "AIW0")]
    [InlineData("AQW62", MemoryArea.AQ, 62, null, AccessWidth.Word, "AQW62")]
    [InlineData("ID0", MemoryArea.I, 0, null, AccessWidth.DoubleWord, "ID0")]
    [InlineData("MD4", MemoryArea.M, 4, null, AccessWidth.DoubleWord, "MD4")]
    [InlineData("VD300", MemoryArea.V, 300, null, AccessWidth.DoubleWord, "VD300")]
    [InlineData("SMD36", MemoryArea.SM, 36, null, AccessWidth.DoubleWord, "SMD36")]
    [InlineData("  VB0100 ", MemoryArea.V, 100, null, AccessWidth.Byte, "VB100")]
    [InlineData("VD65532", MemoryArea.V, 65532, null, AccessWidth.DoubleWord, "VD65532")]
    [InlineData("t37", MemoryArea.T, 37, null, AccessWidth.Word, "T37")]
    [InlineData("C5", MemoryArea.C, 5, null, AccessWidth.Word, "C5")]
    [InlineData("T0", MemoryArea.T, 0, null, AccessWidth.Word, "T0")]
    public void TryParse_ValidText_ReadsAreaOffsetBitAndWidth(string text, MemoryArea area, int offset, int? bit, AccessWidth width, string canonical)
    {
        PlcAddress.TryParse(text, out var address, out var error).Should().BeTrue(error?.Message);

        address.Area.Should().Be(area);
        address.ByteOffset.Should().Be(offset);
        address.Bit.Should().Be(bit);
        address.Width.Should().Be(width);
        address.ToString().Should().Be(canonical);
    }

    [Theory]
    [InlineData(null, AddressErrorKind.Empty, "address is empty")]
    [InlineData("   ", AddressErrorKind.Empty, "address is empty")]
    [InlineData("X0.0", AddressErrorKind.UnknownArea, "unknown memory area")]
    [InlineData("T37.0", AddressErrorKind.UnexpectedBitNumber, "T37 is the timer's current value and takes no bit number; the panel does not read timer bits")]
    [InlineData("TW37", AddressErrorKind.MissingByteNumber, "a timer is written T and its number (T37)")]
    [InlineData("C", AddressErrorKind.MissingByteNumber, "a counter is written C and its number (C5)")]
    [InlineData("C5X", AddressErrorKind.TrailingText, "unexpected 'X' after the address")]
    [InlineData("T99999", AddressErrorKind.ByteNumberTooLarge, "timer number 99999 is larger than 65535")]
    [InlineData("AC0", AddressErrorKind.UnknownArea, "accumulators")]
    [InlineData("HC0", AddressErrorKind.UnknownArea, "high-speed counters")]
    [InlineData("LB0", AddressErrorKind.UnknownArea, "local memory")]
    [InlineData("VB", AddressErrorKind.MissingByteNumber, "a byte number must follow 'VB'")]
    [InlineData("V", AddressErrorKind.MissingByteNumber, "a byte number must follow 'V'")]
    [InlineData("VW65536", AddressErrorKind.ByteNumberTooLarge, "byte number 65536 is larger than 65535")]
    [InlineData("VB99999999999999", AddressErrorKind.ByteNumberTooLarge, "is larger than 65535")]
    [InlineData("M10", AddressErrorKind.MissingBitNumber, "needs a bit number (M10.0) or a width letter (MB10)")]
    [InlineData("M10.", AddressErrorKind.MissingBitNumber, "the bit number after '.' is missing")]
    [InlineData("M10.8", AddressErrorKind.BitOutOfRange, "bit number 8 is outside 0-7")]
    [InlineData("I0.12", AddressErrorKind.BitOutOfRange, "bit number 12 is outside 0-7")]
    [InlineData("VB10.3", AddressErrorKind.UnexpectedBitNumber, "a byte address takes no bit number; write V10.3 for a bit")]
    [InlineData("VD4.0", AddressErrorKind.UnexpectedBitNumber, "a double word address takes no bit number")]
    [InlineData("AI0", AddressErrorKind.WidthNotAllowed, "analog inputs are addressed as words only")]
    [InlineData("AQB0", AddressErrorKind.WidthNotAllowed, "analog outputs are addressed as words only")]
    [InlineData("AIW1", AddressErrorKind.OddAnalogOffset, "analog words start at even byte numbers (AIW0 or AIW2)")]
    [InlineData("VB100X", AddressErrorKind.TrailingText, "unexpected 'X' after the address")]
    [InlineData("I0.3.1", AddressErrorKind.TrailingText, "unexpected '.1' after the address")]
    [InlineData("V B100", AddressErrorKind.MissingByteNumber, "a byte number must follow 'V'")]
    [InlineData("I-1.0", AddressErrorKind.MissingByteNumber, "a byte number must follow 'I'")]
    public void TryParse_BadText_FailsWithKindAndMessage(string? text, AddressErrorKind kind, string messagePart)
    {
        PlcAddress.TryParse(text, out _, out var error).Should().BeFalse();

        error!.Kind.Should().Be(kind);
        error.Message.Should().Contain(messagePart);
    }

    public static TheoryData<PlcAddress> EveryForm()
    {
        var data = new TheoryData<PlcAddress>();
        foreach (var area in new[] { MemoryArea.I, MemoryArea.Q, MemoryArea.M, MemoryArea.V, MemoryArea.SM, MemoryArea.S })
        {
            foreach (var offset in new[] { 0, 1, 9, 255, 10239, PlcAddress.MaxByteOffset })
            {
                data.Add(PlcAddress.ForBit(area, offset, offset % 8));
                data.Add(PlcAddress.ForBytes(area, offset, AccessWidth.Byte));
                data.Add(PlcAddress.ForBytes(area, offset, AccessWidth.Word));
                data.Add(PlcAddress.ForBytes(area, offset, AccessWidth.DoubleWord));
            }
        }

        foreach (var offset in new[] { 0, 2, 62, 65534 })
        {
            data.Add(PlcAddress.ForBytes(MemoryArea.AI, offset, AccessWidth.Word));
            data.Add(PlcAddress.ForBytes(MemoryArea.AQ, offset, AccessWidth.Word));
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(EveryForm))]
    public void Parse_CanonicalText_RoundTripsToTheSameAddress(PlcAddress address)
    {
        PlcAddress.Parse(address.ToString()).Should().Be(address);
        PlcAddress.Parse(address.ToString().ToLowerInvariant()).Should().Be(address);
    }

    [Fact]
    public void TryParse_RandomText_NeverThrows()
    {
        var random = new Random(20261121);
        const string alphabet = "IQMVSABCDWLT0123456789.. -+x\u00e9\0";
        for (var i = 0; i < 20000; i++)
        {
            var chars = new char[random.Next(0, 12)];
            for (var c = 0; c < chars.Length; c++)
            {
                chars[c] = alphabet[random.Next(alphabet.Length)];
            }

            var text = new string(chars);
            var ok = PlcAddress.TryParse(text, out var address, out var error);

            if (ok)
            {
                error.Should().BeNull(text);
                PlcAddress.Parse(address.ToString()).Should().Be(address, text);
            }
            else
            {
                error!.Message.Should().StartWith(text.Trim().Length == 0 ? "address is empty" : "'", text);
            }
        }
    }

    [Fact]
    public void TryParse_TenThousandDigits_QuotesTheTextShortened()
    {
        PlcAddress.TryParse("VB" + new string('9', 10_000), out _, out var error).Should().BeFalse();

        error!.Kind.Should().Be(AddressErrorKind.ByteNumberTooLarge);
        error.Message.Should().Be($"'VB{new string('9', 37)}...': byte number {new string('9', 40)}... is larger than 65535");
    }

    [Fact]
    public void TryParse_ControlCharacter_ShowsItAsItsCode()
    {
        PlcAddress.TryParse("VB\u00001", out _, out var error).Should().BeFalse();

        error!.Message.Should().StartWith("'VB<16#00>1'");
    }

    [Fact]
    public void Parse_BadText_ThrowsFormatExceptionWithTheReason()
    {
        var act = () => PlcAddress.Parse("M10.8");

        act.Should().Throw<FormatException>().WithMessage("*bit number 8 is outside 0-7*");
    }

    [Fact]
    public void LastByte_DoubleWord_IsThreePastTheFirst()
    {
        PlcAddress.Parse("VD300").LastByte.Should().Be(303);
        PlcAddress.Parse("VW300").LastByte.Should().Be(301);
        PlcAddress.Parse("V300.7").LastByte.Should().Be(300);
    }
}
