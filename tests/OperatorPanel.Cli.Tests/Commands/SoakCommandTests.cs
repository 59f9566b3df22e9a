namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>The option checks of <c>opanel soak</c>; the soak itself runs in the integration tests (socat).</summary>
public sealed class SoakCommandTests
{
    [Fact]
    public void Soak_UnknownProfile_ExitsBadInputNamingTheProfiles()
    {
        var (exit, _, error) = CliRunner.Run("soak", "--profile", "storm");

        exit.Should().Be(ExitCodes.BadInput);
        error.Should().Contain("no fault profile 'storm'").And.Contain("flips").And.Contain("mixed");
    }

    [Theory]
    [InlineData("0")]
    [InlineData("-1")]
    public void Soak_MinutesNotPositive_ExitsBadInput(string minutes)
    {
        var (exit, _, error) = CliRunner.Run("soak", "--minutes", minutes);

        exit.Should().Be(ExitCodes.BadInput);
        error.Should().Contain($"--minutes {minutes}");
    }

    [Fact]
    public void Soak_TooManyLines_ExitsBadInput()
    {
        var (exit, _, error) = CliRunner.Run("soak", "--lines", "17");

        exit.Should().Be(ExitCodes.BadInput);
        error.Should().Contain("--lines 17: give 1 to 16");
    }
}
