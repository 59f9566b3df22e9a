using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Values;

public sealed class ValueFormatterTests
{
    [Theory]
    [InlineData("01", AccessWidth.Bit, DisplayFormat.Bool, "1")]
    [InlineData("00", AccessWidth.Bit, DisplayFormat.Bool, "0")]
    [InlineData("FF", AccessWidth.Byte, DisplayFormat.Unsigned, "255")]
    [InlineData("FF", AccessWidth.Byte, DisplayFormat.Signed, "-1")]
    [InlineData("80", AccessWidth.Byte, DisplayFormat.Signed, "-128")]
    [InlineData("7F", AccessWidth.Byte, DisplayFormat.Signed, "127")]
    [InlineData("0A", AccessWidth.Byte, DisplayFormat.Hex, "16#0A")]
    [InlineData("0A", AccessWidth.Byte, DisplayFormat.Binary, "2#0000_1010")]
    [InlineData("41", AccessWidth.Byte, DisplayFormat.Ascii, "A")]
    [InlineData("003C", AccessWidth.Word, DisplayFormat.Unsigned, "60")] //        VW104 = VB104 high, VB105 low
    [InlineData("FFFB", AccessWidth.Word, DisplayFormat.Signed, "-5")]
    [InlineData("8000", AccessWidth.Word, DisplayFormat.Signed, "-32768")]
    [InlineData("0A3F", AccessWidth.Word, DisplayFormat.Hex, "16#0A3F")]
    [InlineData("0A3F", AccessWidth.Word, DisplayFormat.Binary, "2#0000_1010_0011_1111")]
    [InlineData("4F4B", AccessWidth.Word, DisplayFormat.Ascii, "OK")]
    [InlineData("00000457", AccessWidth.DoubleWord, DisplayFormat.Unsigned, "1111")] // docs/protocol-v2.md 5.2: VD100 = 1111
    [InlineData("FFFFFFFF", AccessWidth.DoubleWord, DisplayFormat.Unsigned, "4294967295")]
    [InlineData("FFFFFFFF", AccessWidth.DoubleWord, DisplayFormat.Signed, "-1")]
    [InlineData("80000000", AccessWidth.DoubleWord, DisplayFormat.Signed, "-2147483648")]
    [InlineData("DEADBEEF", AccessWidth.DoubleWord, DisplayFormat.Hex, "16#DEADBEEF")]
    [InlineData("3F800000", AccessWidth.DoubleWord, DisplayFormat.Float, "1")] //     REAL 1.0, big-endian
    [InlineData("41480000", AccessWidth.DoubleWord, DisplayFormat.Float, "12.5")]
    [InlineData("BE800000", AccessWidth.DoubleWord, DisplayFormat.Float, "-0.25")]
    [InlineData("7FC00000", AccessWidth.DoubleWord, DisplayFormat.Float, "NaN")]
    [InlineData("41423132", AccessWidth.DoubleWord, DisplayFormat.Ascii, "AB12")]
    [InlineData("41000A7F", AccessWidth.DoubleWord, DisplayFormat.Ascii, "A...")] //   unprintable bytes show as '.'
    public void Format_Bytes_GivesTheText(string raw, AccessWidth width, DisplayFormat format, string expected) =>
        ValueFormatter.Format(Hex.Parse(raw), width, format).Should().Be(expected);

    [Theory]
    [InlineData("0000", AccessWidth.Word, DisplayFormat.Float)]
    [InlineData("00", AccessWidth.Byte, DisplayFormat.Bool)]
    [InlineData("01", AccessWidth.Bit, DisplayFormat.Hex)]
    [InlineData("0000", AccessWidth.DoubleWord, DisplayFormat.Unsigned)]
    public void Format_WidthOrFormatMismatch_Throws(string raw, AccessWidth width, DisplayFormat format)
    {
        var act = () => ValueFormatter.Format(Hex.Parse(raw), width, format);

        act.Should().Throw<ArgumentException>();
    }

    public static TheoryData<string, DisplayFormat> RoundTrips() => new()
    {
        { "VB10", DisplayFormat.Unsigned }, { "VB10", DisplayFormat.Signed }, { "VB10", DisplayFormat.Hex }, { "VB10", DisplayFormat.Binary },
        { "VW10", DisplayFormat.Unsigned }, { "VW10", DisplayFormat.Signed }, { "VW10", DisplayFormat.Hex }, { "VW10", DisplayFormat.Binary },
        { "VD10", DisplayFormat.Unsigned }, { "VD10", DisplayFormat.Signed }, { "VD10", DisplayFormat.Hex }, { "VD10", DisplayFormat.Binary },
        { "VD10", DisplayFormat.Float }, { "M0.0", DisplayFormat.Bool },
    };

    [Theory]
    [MemberData(nameof(RoundTrips))]
    public void Format_ThenParse_GivesTheSameBytes(string addressText, DisplayFormat format)
    {
        var address = PlcAddress.Parse(addressText);
        var random = new Random(7);
        for (var i = 0; i < 200; i++)
        {
            var raw = new byte[address.Width.ByteCount()];
            random.NextBytes(raw);
            if (address.Width == AccessWidth.Bit)
            {
                raw[0] &= 1;
            }

            if (format == DisplayFormat.Float && !float.IsFinite(BitConverter.UInt32BitsToSingle(System.Buffers.Binary.BinaryPrimitives.ReadUInt32BigEndian(raw))))
            {
                continue;
            }

            var text = ValueFormatter.Format(raw, address.Width, format);

            ValueParser.TryParse(text, address, format, out var parsed, out var error).Should().BeTrue(error?.Message);
            parsed.Should().Equal(raw, $"{text} in {format}");
        }
    }
}
