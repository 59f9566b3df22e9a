using OperatorPanel.Cli.History;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.History;

/// <summary>--since, --from and --to as a technician types them.</summary>
public sealed class TimeRangeTests
{
    private readonly ManualTimeProvider _time = new(new DateTimeOffset(2024, 1, 15, 12, 0, 0, TimeSpan.Zero));

    [Theory]
    [InlineData("90s", 90)]
    [InlineData("30m", 1800)]
    [InlineData("2h", 7200)]
    [InlineData("1.5d", 129600)]
    public void TryParse_Since_CountsBackFromNow(string since, int seconds)
    {
        TimeRange.TryParse(since, null, null, _time, out var from, out var to, out _).Should().BeTrue();

        (to - from).TotalSeconds.Should().Be(seconds);
        to.Should().Be(_time.GetUtcNow());
    }

    [Fact]
    public void TryParse_FromAndToUtc_AreTaken()
    {
        TimeRange.TryParse(null, "2024-01-15T08:00:00Z", "2024-01-15T09:30:00Z", _time, out var from, out var to, out _).Should().BeTrue();

        from.Should().Be(new DateTimeOffset(2024, 1, 15, 8, 0, 0, TimeSpan.Zero));
        to.Should().Be(new DateTimeOffset(2024, 1, 15, 9, 30, 0, TimeSpan.Zero));
    }

    [Theory]
    [InlineData("1h", "2024-01-15T08:00:00Z", null, "give --since, or --from and --to, not both")]
    [InlineData("1w", null, null, "--since '1w': give a number and a unit, e.g. 90s, 30m, 2h or 7d")]
    [InlineData(null, "yesterday", null, "--from 'yesterday': give a time as 2024-01-15T08:00:00Z or 2024-01-15 08:00 (local)")]
    [InlineData(null, "2024-01-15T09:00:00Z", "2024-01-15T08:00:00Z", "--to is before --from")]
    public void TryParse_Bad_SaysWhatToType(string? since, string? from, string? to, string message)
    {
        TimeRange.TryParse(since, from, to, _time, out _, out _, out var error).Should().BeFalse();

        error.Should().Be(message);
    }
}
