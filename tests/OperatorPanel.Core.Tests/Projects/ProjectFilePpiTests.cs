using System.Text.Json.Nodes;
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
