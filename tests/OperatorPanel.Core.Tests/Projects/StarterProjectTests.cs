using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class StarterProjectTests
{
    public static TheoryData<CpuModel, CpuRevision> Profiles()
    {
        var data = new TheoryData<CpuModel, CpuRevision>();
        foreach (var profile in CpuProfiles.All)
        {
            data.Add(profile.Model, profile.Revision);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Profiles))]
    public void Create_EveryCpu_IsAValidProject(CpuModel model, CpuRevision revision)
    {
        var project = StarterProject.Create("Line", CpuProfiles.For(model, revision), new Station(2), "COM1");

        ProjectFile.Check(project).Should().BeEmpty();
    }

    [Fact]
    public void Create_Cpu226_ListsItsTwentyFourInputsAndSixteenOutputs()
    {
        var station = StarterProject.Create("Line", CpuProfiles.For(CpuModel.Cpu226), new Station(5), "/dev/ttyUSB0").Stations[0];

        station.Inputs.Should().HaveCount(24);
        station.Inputs[^1].Should().Be(new IoSymbol("Input_2_7", PlcAddress.Parse("I2.7"), "Local input I2.7"));
        station.Outputs.Should().HaveCount(16);
        station.Outputs[^1].Address.ToString().Should().Be("Q1.7");
        station.Address.Address.Should().Be(5);
        station.Link.PortName.Should().Be("/dev/ttyUSB0");
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, true)]
    [InlineData(CpuModel.Cpu222, true)]
    [InlineData(CpuModel.Cpu224, false)]
    [InlineData(CpuModel.Cpu224XP, false)]
    [InlineData(CpuModel.Cpu226, false)]
    public void Create_TheCpusWith4096ProgramBytes_GetTheCompactHandler(CpuModel model, bool compact)
    {
        foreach (var revision in CpuProfiles.RevisionsOf(model))
        {
            StarterProject.Create("Line", CpuProfiles.For(model, revision), new Station(2), "COM1").Stations[0].Compact.Should().Be(compact, revision.ToString());
        }
    }
}
