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
}
