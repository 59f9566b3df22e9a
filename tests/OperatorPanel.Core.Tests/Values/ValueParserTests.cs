using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;

namespace OperatorPanel.Core.Tests.Values;

public sealed class ValueParserTests
{
    [Theory]
    [InlineData("M0.0", "1", DisplayFormat.Bool, "01")]
    [InlineData("Q0.5", "true", DisplayFormat.Bool, "01")]
    [InlineData("Q0.5", "ON", DisplayFormat.Bool, "01")]
    [InlineData("Q0.5", "off", DisplayFormat.Bool, "00")]
    [InlineData("Q0.5", " False ", DisplayFormat.Bool, "00")]
    [InlineData("VB110", "0", DisplayFormat.Unsigned, "00")]
    [InlineData("VB110", "255", DisplayFormat.Unsigned, "FF")]
    [InlineData("VB110", "+7", DisplayFormat.Unsigned, "07")]
    [InlineData("VB110", "-128", DisplayFormat.Signed, "80")]
    [InlineData("VB110", "127", DisplayFormat.Signed, "7F")]
    [InlineData("VB110", "-1", DisplayFormat.Signed, "FF")]
    [InlineData("VB110", "16#FF", DisplayFormat.Hex, "FF")]
    [InlineData("VB110", "0xff", DisplayFormat.Hex, "FF")]
    [InlineData("VB110", "2A", DisplayFormat.Hex, "2A")] //                bare digits read in the format's own radix
    [InlineData("VB110", "2#1010", DisplayFormat.Binary, "0A")]
    [InlineData("VB110", "2#0000_1010", DisplayFormat.Binary, "0A")]
    [InlineData("VB110", "1010", DisplayFormat.Binary, "0A")]
    [InlineData("VB110", "16#2A", DisplayFormat.Unsigned, "2A")] //        STL constants are read in any integer format
    [InlineData("VB110", "A", DisplayFormat.Ascii, "41")]
    [InlineData("VW104", "60", DisplayFormat.Unsigned, "003C")] //         docs/protocol-v2.md 5.3: VW104 := 60
    [InlineData("VW104", "65535", DisplayFormat.Unsigned, "FFFF")]
    [InlineData("VW104", "-32768", DisplayFormat.Signed, "8000")]
    [InlineData("VW104", "32767", DisplayFormat.Signed, "7FFF")]
    [InlineData("VW104", "16#FFFF", DisplayFormat.Signed, "FFFF")] //      a hex bit pattern takes the unsigned range
    [InlineData("VW104", "16#0A3F", DisplayFormat.Hex, "0A3F")]
    [InlineData("VW104", "'OK'", DisplayFormat.Ascii, "4F4B")]
    [InlineData("VD100", "4294967295", DisplayFormat.Unsigned, "FFFFFFFF")]
    [InlineData("VD100", "1111", DisplayFormat.Unsigned, "00000457")]
    [InlineData("VD100", "-2147483648", DisplayFormat.Signed, "80000000")]
    [InlineData("VD100", "16#DEAD_BEEF", DisplayFormat.Hex, "DEADBEEF")]
    [InlineData("VD120", "12.5", DisplayFormat.Float, "41480000")]
    [InlineData("VD120", "-0.25", DisplayFormat.Float, "BE800000")]
    [InlineData("VD120", "1", DisplayFormat.Float, "3F800000")]
    [InlineData("VD120", "1.5e3", DisplayFormat.Float, "44BB8000")]
    [InlineData("VD120", "0.1", DisplayFormat.Float, "3DCCCCCD")] //         the nearest REAL: precision lost, the number kept
    [InlineData("VD120", "0", DisplayFormat.Float, "00000000")]
    [InlineData("VD120", "-0", DisplayFormat.Float, "80000000")]
    [InlineData("VD120", "0.0e-50", DisplayFormat.Float, "00000000")] //     a zero in any notation is 0
    [InlineData("VD120", "3.4028235e38", DisplayFormat.Float, "7F7FFFFF")] // the largest REAL (the manual: 3.402823E+38)
    [InlineData("VD120", "1.1754944e-38", DisplayFormat.Float, "00800000")] // the smallest normal REAL (the manual: 1.175495E-38)
    [InlineData("VD120", "-1.175495e-38", DisplayFormat.Float, "80800005")]
    [InlineData("VD130", "AB12", DisplayFormat.Ascii, "41423132")]
    [InlineData("VD130", "\"a b!\"", DisplayFormat.Ascii, "61206221")]
    public void TryParse_ValidText_GivesBigEndianBytes(string address, string text, DisplayFormat format, string expected)
    {
        ValueParser.TryParse(text, PlcAddress.Parse(address), format, out var bytes, out var error).Should().BeTrue(error?.Message);

        Convert.ToHexString(bytes.AsSpan()).Should().Be(expected);
        error.Should().BeNull();
    }

    [Theory]
    [InlineData("VB110", "", DisplayFormat.Unsigned, ValueErrorKind.Empty, "VB110: no value given")]
    [InlineData("VB110", "256", DisplayFormat.Unsigned, ValueErrorKind.OutOfRange, "VB110: 256 is outside 0..255, the range of an unsigned byte (a signed byte takes -128..127)")]
    [InlineData("VB110", "-1", DisplayFormat.Unsigned, ValueErrorKind.OutOfRange, "VB110: -1 is outside 0..255")]
    [InlineData("VB110", "-129", DisplayFormat.Signed, ValueErrorKind.OutOfRange, "VB110: -129 is outside -128..127, the range of a signed byte")]
    [InlineData("VB110", "128", DisplayFormat.Signed, ValueErrorKind.OutOfRange, "VB110: 128 is outside -128..127")]
    [InlineData("VB110", "16#100", DisplayFormat.Hex, ValueErrorKind.OutOfRange, "VB110: 16#100 is outside 16#00..16#FF, the range of a byte")]
    [InlineData("VB110", "2#1_0000_0000", DisplayFormat.Binary, ValueErrorKind.OutOfRange, "VB110: 2#1_0000_0000 is outside 2#0000_0000..2#1111_1111")]
    [InlineData("VB110", "12a", DisplayFormat.Unsigned, ValueErrorKind.Malformed, "VB110: '12a' is not a whole number; write e.g. 42, -7, 16#2A or 2#1010")]
    [InlineData("VB110", "16#", DisplayFormat.Hex, ValueErrorKind.Malformed, "VB110: '16#' is not a hexadecimal number")]
    [InlineData("VB110", "2#102", DisplayFormat.Binary, ValueErrorKind.Malformed, "VB110: '2#102' is not a binary number")]
    [InlineData("VB110", "1_000", DisplayFormat.Unsigned, ValueErrorKind.Malformed, "is not a whole number")]
    [InlineData("VW104", "65536", DisplayFormat.Unsigned, ValueErrorKind.OutOfRange, "VW104: 65536 is outside 0..65535, the range of an unsigned word (a signed word takes -32768..32767)")]
    [InlineData("VW104", "-32769", DisplayFormat.Signed, ValueErrorKind.OutOfRange, "VW104: -32769 is outside -32768..32767, the range of a signed word")]
    [InlineData("VD100", "4294967296", DisplayFormat.Unsigned, ValueErrorKind.OutOfRange, "VD100: 4294967296 is outside 0..4294967295")]
    [InlineData("VD100", "99999999999999999999999", DisplayFormat.Unsigned, ValueErrorKind.OutOfRange, "is outside 0..4294967295")]
    [InlineData("VD100", "2147483648", DisplayFormat.Signed, ValueErrorKind.OutOfRange, "VD100: 2147483648 is outside -2147483648..2147483647, the range of a signed double word")]
    [InlineData("VD120", "abc", DisplayFormat.Float, ValueErrorKind.Malformed, "VD120: 'abc' is not a REAL number")]
    [InlineData("VD120", "1e39", DisplayFormat.Float, ValueErrorKind.OutOfRange,
        "VD120: 1e39 is too large for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38); write a number inside that range")]
    [InlineData("VD120", "-1e400", DisplayFormat.Float, ValueErrorKind.OutOfRange, "VD120: -1e400 is too large for a REAL")]
    [InlineData("VD120", "Infinity", DisplayFormat.Float, ValueErrorKind.NotFinite,
        "VD120: Infinity is not a number a REAL can hold (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38)")]
    [InlineData("VD120", "NaN", DisplayFormat.Float, ValueErrorKind.NotFinite, "VD120: NaN is not a number a REAL can hold")]
    [InlineData("VD120", "1.5e-50", DisplayFormat.Float, ValueErrorKind.OutOfRange,
        "VD120: 1.5e-50 is too close to 0 for a REAL (a REAL holds 0 and numbers from ±1.175495E-38 to ±3.402823E+38): it would be stored as 0; write 0 or a number inside that range")]
    [InlineData("VD120", "-1e-400", DisplayFormat.Float, ValueErrorKind.OutOfRange, "VD120: -1e-400 is too close to 0 for a REAL")] // 0 already as a double
    [InlineData("VD120", "1e-40", DisplayFormat.Float, ValueErrorKind.OutOfRange, "it would be stored as 1E-40")] //               a denormal, below the manual's range
    [InlineData("VD120", "1.1754942e-38", DisplayFormat.Float, ValueErrorKind.OutOfRange, "VD120: 1.1754942e-38 is too close to 0 for a REAL")] // the largest denormal
    [InlineData("VW104", "1.5", DisplayFormat.Float, ValueErrorKind.FormatDoesNotFit, "VW104: a REAL (Float) needs a double word such as VD100")]
    [InlineData("VB110", "1", DisplayFormat.Bool, ValueErrorKind.FormatDoesNotFit, "VB110: Bool takes a bit address, not a byte")]
    [InlineData("M0.0", "1", DisplayFormat.Unsigned, ValueErrorKind.FormatDoesNotFit, "M0.0: Unsigned needs a byte, word or double word, not a bit")]
    [InlineData("M0.0", "2", DisplayFormat.Bool, ValueErrorKind.Malformed, "M0.0: '2' is not a bit value; write 0/1, true/false or on/off")]
    [InlineData("M0.0", "yes", DisplayFormat.Bool, ValueErrorKind.Malformed, "is not a bit value")]
    [InlineData("VD130", "ABC", DisplayFormat.Ascii, ValueErrorKind.WrongLength, "VD130: 'ABC' has 3 characters; a double word takes exactly 4 ASCII characters")]
    [InlineData("VB110", "'AB'", DisplayFormat.Ascii, ValueErrorKind.WrongLength, "a byte takes exactly 1 ASCII character")]
    [InlineData("VW104", "Aé", DisplayFormat.Ascii, ValueErrorKind.NotAscii, "VW104: 'Aé' holds a character outside printable ASCII")]
    public void TryParse_BadText_RefusesNamingValueAddressAndRange(string address, string text, DisplayFormat format, ValueErrorKind kind, string message)
    {
        ValueParser.TryParse(text, PlcAddress.Parse(address), format, out var bytes, out var error).Should().BeFalse();

        error!.Kind.Should().Be(kind);
        error.Message.Should().Contain(message);
        bytes.IsDefault.Should().BeTrue();
    }

    [Fact]
    public void TryParse_TenThousandDigits_QuotesTheValueShortened()
    {
        ValueParser.TryParse(new string('1', 10_000), PlcAddress.Parse("VB0"), DisplayFormat.Unsigned, out _, out var error).Should().BeFalse();

        error!.Message.Should().StartWith($"VB0: {new string('1', 40)}... ").And.NotContain(new string('1', 41));
        error.Message.Length.Should().BeLessThan(200);
    }

    [Fact]
    public void TryParse_NullText_IsEmptyNotAnException()
    {
        ValueParser.TryParse(null, PlcAddress.Parse("VB0"), DisplayFormat.Unsigned, out _, out var error).Should().BeFalse();

        error!.Kind.Should().Be(ValueErrorKind.Empty);
    }
}
