using System.Text.Json.Nodes;

namespace OperatorPanel.Cli.Tests.Commands;

/// <summary>
/// A station whose project says where its handler lives (<c>"handlerVFirst"</c>, for a handler generated with
/// <c>--buffer</c>): generate puts it there unless --buffer says otherwise, the --demo PLC runs it there, and writes keep
/// off its bytes there instead of the top of V, before anything is sent.
/// </summary>
public sealed class HandlerVFirstCommandTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("opanel-handler-vfirst-").FullName;

    [Fact]
    public void Generate_ProjectHandlerVFirst_PutsTheHandlerThere()
    {
        var run = CliRunner.Run("generate", MovedProject(1000), "-o", Out);

        run.ExitCode.Should().Be(0, run.Error);
        File.ReadAllText(Path.Combine(Out, "PLC_2-symbols.txt")).Should().StartWith("OP_BUF\tVB1000\t", "the project is the one source of V_FIRST");
    }

    [Fact]
    public void Generate_BufferOption_WinsOverTheProjectsHandlerVFirst()
    {
        var run = CliRunner.Run("generate", MovedProject(1000), "-o", Out, "--buffer", "VB2000");

        run.ExitCode.Should().Be(0, run.Error);
        File.ReadAllText(Path.Combine(Out, "PLC_2-symbols.txt")).Should().StartWith("OP_BUF\tVB2000\t");
    }

    [Fact]
    public void Identify_DemoOfAMovedHandler_ReportsTheProjectsPlace()
    {
        var run = CliRunner.Run("identify", "--project", MovedProject(1000), "--demo");

        run.ExitCode.Should().Be(0, run.Error);
        run.Out.Should().Contain("handler V     VB1000-VB1605 (606 bytes", "the demo PLC runs the handler where the project says");
    }

    [Fact]
    public void Write_TopOfVWithTheHandlerMoved_IsWrittenAndConfirmed()
    {
        // VB8000 lies in a CPU 224's default handler place (VB7586-VB8191): the program's byte once the handler is at VB1000.
        var run = CliRunner.Run("write", "VB8000=9", "--project", MovedProject(1000), "--demo");

        run.ExitCode.Should().Be(0, run.Out + run.Error);
        run.Out.Should().Be("VB8000   0 -> 9  confirmed" + Environment.NewLine);
    }

    [Fact]
    public void Write_MovedHandlersOwnVBytes_RefusedBeforeSendingNamingTheProjectsRange()
    {
        var run = CliRunner.Run("write", "VW200=1", "VW1604=9", "--project", MovedProject(1000), "--demo");

        run.ExitCode.Should().Be(1);
        run.Out.Should().BeEmpty("nothing is written when one assignment is refused");
        run.Error.Should().Be("opanel: VW1604 is in the handler's own V bytes VB1000-VB1605 (where the project's \"handlerVFirst\" puts the full handler's "
            + "buffer, work bytes and list; IDENTIFY says where a station's are); nothing written" + Environment.NewLine);
    }

    [Fact]
    public void ProjectCheck_HandlerVFirstPastTheEndOfV_NamesThePathAndTheAllowedRange()
    {
        var file = MovedProject(7600);

        var run = CliRunner.Run("project", "check", file);

        run.ExitCode.Should().Be(1);
        run.Out.Split(Environment.NewLine, StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            $"{file}: $.stations[0].handlerVFirst: the handler needs VB7600-VB8205 (606 bytes) but the CPU 224 has VB0-VB8191; \"handlerVFirst\" may be "
                + "3-7586 for the full handler (leave it out for the top of V, where generate puts it by default)",
            $"{file}: 1 problem");
    }

    [Fact]
    public void ProjectCheck_WritableTagInTheMovedHandlersBytes_IsAProblemAtTheTag()
    {
        var file = MovedProject(1000);
        var root = JsonNode.Parse(File.ReadAllText(file))!;
        root["stations"]![0]!["tags"] = new JsonArray(new JsonObject { ["symbol"] = "Speed", ["address"] = "VW1000", ["writable"] = true });
        File.WriteAllText(file, root.ToJsonString());

        var run = CliRunner.Run("project", "check", file);

        run.ExitCode.Should().Be(1);
        run.Out.Should().StartWith($"{file}: $.stations[0].tags[0]: tag Speed (VW1000) is writable, but VW1000 is in the handler's own V bytes VB1000-VB1605 ")
            .And.EndWith($"{file}: 1 problem{Environment.NewLine}");
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    private string Out => Path.Combine(_folder, "out");

    /// <summary>A CPU 224 station 2 whose handler the project places at <paramref name="vFirst"/>.</summary>
    private string MovedProject(int vFirst)
    {
        var file = Path.Combine(_folder, "line.opproj");
        CliRunner.Run("project", "new", "--cpu", "224", "--station", "2", "--port", "COM1", "-o", file, "--force").ExitCode.Should().Be(0);
        var root = JsonNode.Parse(File.ReadAllText(file))!;
        root["stations"]![0]!["handlerVFirst"] = vFirst;
        File.WriteAllText(file, root.ToJsonString());
        return file;
    }
}
