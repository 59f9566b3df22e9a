using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Tests.Messages;

public sealed class QuotedTextTests
{
    [Fact]
    public void Readable_LongQuotedWord_KeepsItsClosingQuoteAndColon()
    {
        var message = QuotedText.Readable($"'{new string('7', 500)}': unknown memory area");

        message.Should().Be($"'{new string('7', 39)}...': unknown memory area");
    }

    [Fact]
    public void Readable_LongRunOfQuotes_StaysShort()
    {
        var message = QuotedText.Readable($"'{new string('\'', 10_000)}': unknown memory area");

        message.Length.Should().BeLessThan(80);
    }

    [Fact]
    public void OneLine_ControlCharactersIncludingTabLineFeedDelAndC1_ShownAsCodesNothingCut()
    {
        var shown = QuotedText.OneLine("Fil\u001b[31mler\u0000\t\n\u007f\u0085" + new string('x', 100));

        shown.Should().Be("Fil<16#1B>[31mler<16#00><16#09><16#0A><16#7F><16#85>" + new string('x', 100));
    }

    [Fact]
    public void OneLine_PrintableTextWithUmlautsAndLamps_ComesBackAsItIs()
    {
        const string Text = "Zähler ● ○ 系统";

        QuotedText.OneLine(Text).Should().BeSameAs(Text);
    }
}
