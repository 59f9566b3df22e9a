namespace OperatorPanel.Cli.Tests.Fuzz;

/// <summary>
/// Odd address and value arguments to <c>opanel address</c>, <c>read</c> and <c>write</c>: each gives exit 1 and one
/// "opanel: " message that quotes what was wrong, never a stack trace; random text (seeded) likewise.
/// </summary>
public sealed class AddressArgumentFuzzTests
{
    private static readonly string[] OddAddresses =
    [
        "VW99999", "I9.9", "V.1", "VB-1", "16#GG", "", " ", "V", "VB", "VW", "I0.", "I.0", "Q0.8", "M32.0", "SMB65536",
        "VB4294967296", "VB99999999999999999999", "VD-0", "VB1e3", "VB0x10", "V B0", "\0", "VB\0", "\u00C4B0", "AIW1",
        "AQW-2", "T0.0", "CW0", "T256", "AC0", "HC0", "LB0", "SB32", "VW200=", "=1", "VB0,VB1", "'VB0'",
        new string('V', 10_000), "VB" + new string('9', 10_000),
    ];

    private static readonly string[] OddWrites =
    [
        "VD10=abc", "Q0.1=2", "VB100=256", "VB100=-129", "VW100=65536", "VW100=16#GG", "VW100=16#", "VB0=", "=5", "VB0==1",
        "VB0=1=2", "VD0=1e40", "VD0=NaN", "VD0='ABCDE'", "VD0='AB", "M0.0=yes", "M0.0=-1", "VW0=99999999999999999999",
        "VB0=" + new string('1', 10_000), "VW99999=1", "I9.9=1", "V.1=1", "VB-1=1", "IB0=1", "\0=\0",
    ];

    public static TheoryData<string> Addresses() => [.. OddAddresses];

    public static TheoryData<string> Writes() => [.. OddWrites];

    [Theory]
    [MemberData(nameof(Addresses))]
    public void Address_OddText_ExitsOneWithAMessageNamingIt(string text) =>
        ExpectRefusal(CliRunner.Run("address", text, "--cpu", "224"), text);

    [Theory]
    [MemberData(nameof(Addresses))]
    public void Read_OddAddress_ExitsOneWithAMessageNamingIt(string text) =>
        ExpectRefusal(CliRunner.Run("read", text, "--demo"), text);

    [Theory]
    [MemberData(nameof(Writes))]
    public void Write_OddAssignment_ExitsOneWithAMessageNamingIt(string text) =>
        ExpectRefusal(CliRunner.Run("write", text, "--demo"), text[..text.IndexOf('=', StringComparison.Ordinal)]);

    [Fact]
    public void Address_RandomText_NeverAStackTrace()
    {
        var random = new Random(224);
        const string Alphabet = "IQMVSBWDAHCTLXZ0123456789.#+ =,'\"\0\u00C4";
        var failures = new List<string>();
        for (var i = 0; i < 300; i++)
        {
            var text = new string([.. Enumerable.Range(0, random.Next(0, 12)).Select(_ => Alphabet[random.Next(Alphabet.Length)])]);
            var run = CliRunner.Run("address", text, "--cpu", "224");
            if (run.ExitCode is not (0 or 1) || run.Error.Contains("Exception", StringComparison.Ordinal) || run.Error.Contains("   at ", StringComparison.Ordinal)
                || (run.ExitCode == 1 && !run.Error.StartsWith("opanel: ", StringComparison.Ordinal)))
            {
                failures.Add($"'{text}': exit {run.ExitCode}, {run.Error}");
            }
        }

        failures.Should().BeEmpty();
    }

    private static void ExpectRefusal((int ExitCode, string Out, string Error) run, string named)
    {
        run.ExitCode.Should().Be(1, run.Out + run.Error);
        run.Error.Should().StartWith("opanel: ").And.NotContain("Exception").And.NotContain("   at ");
        run.Error.Length.Should().BeLessThan(400, "a message quotes what was wrong, not all of it");
        var quoted = named.Trim().Length > 30 ? named.Trim()[..30] : named.Trim();
        if (quoted.Length > 0 && !quoted.Contains('\0', StringComparison.Ordinal))
        {
            run.Error.Should().Contain(quoted, "the message names what was wrong");
        }
    }
}
