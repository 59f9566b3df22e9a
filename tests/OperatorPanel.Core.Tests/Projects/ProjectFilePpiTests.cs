using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>A bus's link "protocol": freeport unless the file says ppi; a PPI bus's line settings checked against what PPI can do.</summary>
public sealed class ProjectFilePpiTests
{
    [Fact]
    public void Parse_FieldMissing_TheBusIsFreeportAndTheFileSavesAsBefore()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;

        project.Stations.Should().OnlyContain(s => s.Link.Protocol == LinkProtocol.Freeport);
        ProjectFile.Format(project).Should().NotContain("\"protocol\"");
    }

    [Fact]
    public void Parse_PpiAt19200_EightEvenOne_RoundTrips()
    {
        var tree = PpiTree(baud: 19200);

        var project = ProjectFile.Parse(tree.ToJsonString()).Project!;
        var reloaded = ProjectFile.Parse(ProjectFile.Format(project)).Project!;

        var link = project.Stations[0].Link;
        (link.Protocol, link.BaudRate, link.Parity, link.DataBits, link.StopBits).Should().Be((LinkProtocol.Ppi, 19200, Parity.Even, 8, 1));
        reloaded.Should().BeEquivalentTo(project, o => o.ComparingRecordsByMembers());
    }

    [Theory]
    [InlineData(38400)]
    [InlineData(4800)]
    public void Parse_PpiAtAFreeportOnlyRate_NamesThePpiRates(int baud)
    {
        BadFile.SingleProblem(PpiTree(baud).ToJsonString()).Should().Be(
            new ProjectFileError("$.stations[0].link.baud", $"PPI runs at 9600, 19200, 187500 baud, not {baud}"));
    }

    [Fact]
    public void Parse_PpiWithoutEvenParity_SaysPpiIs8E1()
    {
        var tree = PpiTree(9600);
        tree.Station()["link"]!["parity"] = "none";

        BadFile.SingleProblem(tree.ToJsonString()).Message.Should().Contain("8 data bits, even parity, one stop bit");
    }

    [Fact]
    public void Parse_PpiOverTheRadioModule_Refused()
    {
        var tree = PpiTree(9600);
        tree.Station()["link"]!["kind"] = "radioModule";

        BadFile.SingleProblem(tree.ToJsonString()).Message.Should().Contain("needs the cable");
    }

    [Fact]
    public void Parse_UnknownProtocol_NamesTheField()
    {
        var tree = SampleProject.Tree();
        tree.Station()["link"]!["protocol"] = "mpi";

        BadFile.SingleProblem(tree.ToJsonString()).Location.Should().Be("$.stations[0].link.protocol");
    }

    [Fact]
    public void Parse_PpiStationWithAnalogTimerCounterAndSTags_AcceptedSignedByDefault()
    {
        var tree = PpiTree(9600);
        var tags = tree.Station()["tags"]!.AsArray();
        tags.Add(new JsonObject { ["symbol"] = "TankLevelRaw", ["address"] = "AIW0" });
        tags.Add(new JsonObject { ["symbol"] = "ValveSetpoint", ["address"] = "AQW2", ["writable"] = true });
        tags.Add(new JsonObject { ["symbol"] = "FillTimer", ["address"] = "T37" });
        tags.Add(new JsonObject { ["symbol"] = "Bottles", ["address"] = "C5" });
        tags.Add(new JsonObject { ["symbol"] = "Steps", ["address"] = "SB0", ["writable"] = true });
        tree.Station()["alarms"]!.AsArray().Add(new JsonObject { ["flag"] = "S1.2", ["text"] = "Step 10 stuck" });

        var result = ProjectFile.Parse(tree.ToJsonString());

        result.Errors.Should().BeEmpty();
        var station = result.Project!.Stations[0];
        station.Tags.TakeLast(5).Select(t => (t.Address.ToString(), t.Format, t.Writable)).Should().Equal(
            ("AIW0", DisplayFormat.Signed, false), ("AQW2", DisplayFormat.Signed, true), ("T37", DisplayFormat.Signed, false),
            ("C5", DisplayFormat.Signed, false), ("SB0", DisplayFormat.Unsigned, true));
        station.Alarms[^1].Flag.Should().Be(PlcAddress.Parse("S1.2"));
    }

    [Fact]
    public void Parse_FreeportStationWithAnAnalogTag_RefusedSayingWhyAndThatPpiReadsIt()
    {
        var tree = SampleProject.Tree();
        tree.Station()["tags"]!.AsArray().Add(new JsonObject { ["symbol"] = "TankLevelRaw", ["address"] = "AIW0" });

        var problem = BadFile.SingleProblem(tree.ToJsonString());

        problem.Message.Should().Be("AIW0: the Freeport link reads only I, Q, M and V: its handler reaches memory through pointers, and an S7-200 "
            + "pointer cannot reach analog values; copy the analog value to V in the PLC program (MOVW AIW0, VW100) and watch that, or read the "
            + "station over PPI (\"protocol\": \"ppi\"), which reads analog values");
    }

    [Theory]
    [InlineData("AIW0", "AIW0: analog inputs are read-only")]
    [InlineData("T37", "T37: the panel reads timer current values but never writes them: no source says how a CPU takes that write over PPI, and the Freeport handler does not reach them")]
    [InlineData("IB0", "IB0: inputs are read from the field; the panel never writes them")]
    public void Parse_PpiStationWritableTagWhereNothingIsWritten_Refused(string address, string message)
    {
        var tree = PpiTree(9600);
        tree.Station()["tags"]!.AsArray().Add(new JsonObject { ["symbol"] = "X", ["address"] = address, ["writable"] = true });

        BadFile.SingleProblem(tree.ToJsonString()).Message.Should().Be(message);
    }

    private static JsonObject PpiTree(int baud)
    {
        var tree = SampleProject.Tree();
        var link = tree.Station()["link"]!.AsObject();
        link["protocol"] = "ppi";
        link["baud"] = baud;
        link["parity"] = "even";
        link["dataBits"] = 8;
        return tree;
    }
}
