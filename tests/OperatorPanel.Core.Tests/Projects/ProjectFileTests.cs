using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class ProjectFileTests
{
    [Fact]
    public void Load_Sample_HasNoProblems()
    {
        var result = ProjectFile.Load(SampleProject.Path);

        result.Errors.Should().BeEmpty();
        result.Ok.Should().BeTrue();
    }

    [Fact]
    public void Load_Sample_HoldsTheBottleFillerLine()
    {
        var project = ProjectFile.Load(SampleProject.Path).Project!;

        project.Refresh.Should().Be(new RefreshSettings(RefreshMode.Continuous, TimeSpan.FromMilliseconds(100)));
        var filler = project.Stations.Should().ContainSingle().Subject;
        filler.Name.Should().Be("Filler");
        filler.Address.Should().Be(new Station(2));
        filler.Cpu.Should().BeSameAs(CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Current));
        filler.Link.Should().Be(new SerialSettings { PortName = "COM3", BaudRate = 9600, Parity = Parity.None, DataBits = 8, StopBits = 1, Kind = LinkKind.Cable });
        filler.Inputs.Select(i => i.Address.ToString()).Should().Equal(
            "I0.0", "I0.1", "I0.2", "I0.3", "I0.4", "I0.5", "I0.6", "I0.7", "I1.0", "I1.1", "I1.2", "I1.3", "I1.4", "I1.5");
        filler.Outputs.Select(o => o.Address.ToString()).Should().Equal(
            "Q0.0", "Q0.1", "Q0.2", "Q0.3", "Q0.4", "Q0.5", "Q0.6", "Q0.7", "Q1.0", "Q1.1");
        filler.Tags.Should().ContainEquivalentOf(new ProjectTag("BottleCount", PlcAddress.Parse("VD100"), DisplayFormat.Unsigned, true, "Filled bottles counted at the outfeed; the operator may reset it") { Unit = "bottles" });
        filler.Tags.Single(t => t.Symbol == "FillSetpoint").Format.Should().Be(DisplayFormat.Float);
        filler.Alarms.Select(a => a.Flag.ToString()).Should().Equal("M2.0", "M2.1", "M2.2", "M2.3", "M2.4", "M2.5", "M2.6", "M2.7");
        filler.Alarms[0].Should().Be(new AlarmDefinition(PlcAddress.Parse("M2.0"), "Emergency stop pressed", AlarmClass.Fault, true));
    }

    [Fact]
    public void Format_Sample_ReproducesTheFileByteForByte()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;

        ProjectFile.Format(project).Should().Be(SampleProject.Text);
    }

    [Fact]
    public void Parse_FormattedProject_GivesAnEqualProject()
    {
        var original = ProjectFile.Parse(SampleProject.Text).Project!;

        var reloaded = ProjectFile.Parse(ProjectFile.Format(original)).Project;

        reloaded.Should().BeEquivalentTo(original, o => o.ComparingRecordsByMembers());
    }

    [Fact]
    public void Parse_LaxSpellings_AreReadAndWrittenCanonically()
    {
        var tree = SampleProject.Tree();
        tree.Station()["cpu"]!["model"] = "cpu 224";
        tree.Station()["cpu"]!.AsObject().Remove("revision");
        tree.Station()["inputs"]![0]!["address"] = " i0.0 ";
        tree.Station()["tags"]![0]!.AsObject().Remove("format");
        tree["refresh"]!["mode"] = "Triggered";

        var project = ProjectFile.Parse(tree.ToJsonString()).Project!;
        var text = ProjectFile.Format(project);

        text.Should().Contain("\"model\": \"224\"").And.Contain("\"revision\": \"current\"").And.Contain("\"address\": \"I0.0\"")
            .And.Contain("\"mode\": \"triggered\"");
        project.Stations[0].Tags[0].Format.Should().Be(DisplayFormat.Unsigned);
        project.Refresh.Mode.Should().Be(RefreshMode.OnDemand);
    }

    [Fact]
    public void Parse_ByteOrderMark_IsIgnored()
    {
        ProjectFile.Parse("\uFEFF" + SampleProject.Text).Ok.Should().BeTrue();
    }

    [Fact]
    public void Check_ProjectBuiltInCodeWithDuplicateSymbol_ReportsItAtItsSavedPath()
    {
        var project = ProjectFile.Parse(SampleProject.Text).Project!;
        var station = project.Stations[0];
        var broken = project with { Stations = [station with { Tags = station.Tags.SetItem(0, station.Tags[0] with { Symbol = "Horn" }) }] };

        ProjectFile.Check(broken).Should().ContainSingle()
            .Which.Should().Be(new ProjectFileError("$.stations[0].tags[0].symbol", "symbol 'Horn' is already used by $.stations[0].outputs[8]"));
        ProjectFile.Check(project).Should().BeEmpty();
    }
}
