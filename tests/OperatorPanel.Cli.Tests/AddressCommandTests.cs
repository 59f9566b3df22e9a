using System.Text.Json;

namespace OperatorPanel.Cli.Tests;

public sealed class AddressCommandTests
{
    /// <summary>Every CPU, every area at its last unit and one past it (figures from docs/cpu-profiles.md).</summary>
    public static TheoryData<string, string, int, string> Edges()
    {
        var data = new TheoryData<string, string, int, string>();
        (string Cpu, string Revision, int V, int Sm, int AnalogLastWord)[] cpus =
        [
            ("221", "Early", 2047, 179, -1), ("221", "Current", 2047, 179, -1),
            ("222", "Early", 2047, 299, 30), ("222", "Current", 2047, 299, 30),
            ("224", "Early", 5119, 549, 30), ("224", "Current", 8191, 549, 62),
            ("224XP", "Current", 10239, 549, 62), ("226", "Current", 10239, 549, 62),
        ];
        foreach (var (cpu, revision, v, sm, analog) in cpus)
        {
            foreach (var (area, last) in new[] { ("I", 15), ("Q", 15), ("M", 31), ("V", v), ("SM", sm) })
            {
                data.Add(cpu, revision, 0, $"{area}B{last}");
                data.Add(cpu, revision, 0, $"{area}{last}.7");
                data.Add(cpu, revision, 0, $"{area}W{last - 1}");
                data.Add(cpu, revision, 0, $"{area}D{last - 3}");
                data.Add(cpu, revision, 1, $"{area}B{last + 1}");
                data.Add(cpu, revision, 1, $"{area}{last + 1}.0");
                data.Add(cpu, revision, 1, $"{area}W{last}");
                data.Add(cpu, revision, 1, $"{area}D{last - 2}");
            }

            data.Add(cpu, revision, analog < 0 ? 1 : 0, $"AIW{Math.Max(analog, 0)}");
            data.Add(cpu, revision, 1, $"AIW{analog + 2}");
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Edges))]
    public void Address_AtEveryAreaEdgeOfEveryCpu_AcceptsInsideAndRejectsOutside(string cpu, string revision, int exitCode, string address)
    {
        var (exit, output, error) = CliRunner.Run("address", address, "--cpu", cpu, "--revision", revision);

        exit.Should().Be(exitCode, error);
        if (exitCode == 0)
        {
            output.Should().Contain($"address   {address}");
            error.Should().BeEmpty();
        }
        else
        {
            output.Should().BeEmpty();
            error.Should().StartWith("opanel: ").And.Contain(address);
        }
    }

    [Fact]
    public void Address_LowerCaseText_PrintsCanonicalFormAndWritability()
    {
        var (exit, output, _) = CliRunner.Run("address", "vd300", "--cpu", "224");

        exit.Should().Be(0);
        output.Should().Contain("address   VD300").And.Contain("byte      300").And.Contain("width     DoubleWord (4 bytes, last byte 303)").And.Contain("writable  yes");
    }

    [Fact]
    public void Address_Input_IsReportedNotWritable()
    {
        var (exit, output, _) = CliRunner.Run("address", "I0.3", "--cpu", "226");

        exit.Should().Be(0);
        output.Should().Contain("bit       3").And.Contain("writable  no: I0.3: inputs are read from the field");
    }

    [Fact]
    public void Address_Json_PrintsEveryField()
    {
        var (exit, output, _) = CliRunner.Run("address", "SMB30", "--cpu", "224XP", "--json");

        exit.Should().Be(0);
        using var json = JsonDocument.Parse(output);
        json.RootElement.GetProperty("address").GetString().Should().Be("SMB30");
        json.RootElement.GetProperty("area").GetString().Should().Be("SM");
        json.RootElement.GetProperty("byteOffset").GetInt32().Should().Be(30);
        json.RootElement.GetProperty("width").GetString().Should().Be("Byte");
        json.RootElement.GetProperty("writable").GetBoolean().Should().BeFalse("the Freeport handler does not serve SM");
        json.RootElement.GetProperty("notWritableBecause").GetString().Should().StartWith("SMB30: the Freeport handler does not serve SM (no S7-200 manual page found says a pointer reaches it); write a V byte");
        json.RootElement.GetProperty("writableOverPpi").GetBoolean().Should().BeTrue("PPI writes SMB30 and up");
    }

    [Fact]
    public void Address_InvalidWithJson_PrintsTheErrorAsJsonAndExitsOne()
    {
        var (exit, output, _) = CliRunner.Run("address", "VD2046", "--cpu", "221", "--json");

        exit.Should().Be(1);
        using var json = JsonDocument.Parse(output);
        json.RootElement.GetProperty("ok").GetBoolean().Should().BeFalse();
        json.RootElement.GetProperty("error").GetString().Should().Be("VD2046 ends at VB2049, past the last V byte VB2047 of CPU 221");
    }

    [Theory]
    [InlineData("214", "unknown CPU '214'")]
    [InlineData("224XP --revision Early", "CPU 224XP has no Early revision")]
    public void Address_BadCpu_ExitsOneNamingTheProblem(string cpu, string message)
    {
        var args = new List<string> { "address", "VB0", "--cpu" };
        args.AddRange(cpu.Split(' '));
        var (exit, _, error) = CliRunner.Run([.. args]);

        exit.Should().Be(1);
        error.Should().Contain(message);
    }
}
