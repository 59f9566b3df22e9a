using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Tests.Cpu;

public sealed class CpuProfilesTests
{
    [Theory]
    [InlineData(CpuModel.Cpu221, 6, 4, 0, 0, 0, 1, 0x60)]
    [InlineData(CpuModel.Cpu222, 8, 6, 0, 0, 2, 1, 0x00)]
    [InlineData(CpuModel.Cpu224, 14, 10, 0, 0, 7, 1, 0x20)]
    [InlineData(CpuModel.Cpu224XP, 14, 10, 2, 1, 7, 2, 0x20)]
    [InlineData(CpuModel.Cpu226, 24, 16, 0, 0, 7, 2, 0x90)]
    public void For_CurrentRevision_HasTheManualsIoPortsAndSmb6(CpuModel model, int di, int dq, int ai, int aq, int modules, int ports, int smb6)
    {
        var cpu = CpuProfiles.For(model);

        cpu.Revision.Should().Be(CpuRevision.Current);
        (cpu.LocalDigitalInputs, cpu.LocalDigitalOutputs, cpu.LocalAnalogInputs, cpu.LocalAnalogOutputs)
            .Should().Be((di, dq, ai, aq));
        cpu.MaxExpansionModules.Should().Be(modules);
        cpu.CommunicationPorts.Should().Be(ports);
        cpu.CpuIdCode.Should().Be((byte)smb6);
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, CpuRevision.Current, 4096, 4096)]
    [InlineData(CpuModel.Cpu222, CpuRevision.Current, 4096, 4096)]
    [InlineData(CpuModel.Cpu224, CpuRevision.Current, 8192, 12288)]
    [InlineData(CpuModel.Cpu224XP, CpuRevision.Current, 12288, 16384)]
    [InlineData(CpuModel.Cpu226, CpuRevision.Current, 16384, 24576)]
    [InlineData(CpuModel.Cpu221, CpuRevision.Early, 4096, 4096)]
    [InlineData(CpuModel.Cpu224, CpuRevision.Early, 8192, 8192)]
    public void ProgramBytes_PerCpu_AreTheManualsFiguresWithAndWithoutRunModeEdit(CpuModel model, CpuRevision revision, int withEdit, int withoutEdit)
    {
        var cpu = CpuProfiles.For(model, revision);

        (cpu.ProgramBytes, cpu.ProgramBytesWithoutRunModeEdit).Should().Be((withEdit, withoutEdit));
    }

    [Theory]
    [InlineData(CpuRevision.Early, 300, 0b111)]
    [InlineData(CpuRevision.Early, 600, 0b110)]
    [InlineData(CpuRevision.Early, 9600, 0b010)]
    [InlineData(CpuRevision.Early, 38400, 0b000)]
    [InlineData(CpuRevision.Current, 115200, 0b110)]
    [InlineData(CpuRevision.Current, 57600, 0b111)]
    [InlineData(CpuRevision.Current, 9600, 0b010)]
    [InlineData(CpuRevision.Current, 1200, 0b101)]
    public void FreeportBaudCode_PerRevision_MatchesSmb30Table(CpuRevision revision, int baud, int code)
    {
        CpuProfiles.For(CpuModel.Cpu224, revision).FreeportBaudCode(baud).Should().Be(code);
    }

    [Theory]
    [InlineData(CpuRevision.Early, 115200)]
    [InlineData(CpuRevision.Early, 57600)]
    [InlineData(CpuRevision.Current, 300)]
    [InlineData(CpuRevision.Current, 600)]
    [InlineData(CpuRevision.Current, 14400)]
    public void FreeportBaudCode_RateTheRevisionLacks_IsNull(CpuRevision revision, int baud)
    {
        CpuProfiles.For(CpuModel.Cpu224, revision).FreeportBaudCode(baud).Should().BeNull();
    }

    [Fact]
    public void For_ModelWithoutEarlyRevision_ThrowsAndTryForSaysNo()
    {
        CpuProfiles.TryFor(CpuModel.Cpu224XP, CpuRevision.Early, out _).Should().BeFalse();
        var act = () => CpuProfiles.For(CpuModel.Cpu224XP, CpuRevision.Early);
        act.Should().Throw<ArgumentException>().WithMessage("*CPU 224XP has no Early revision*");
    }

    [Theory]
    [InlineData("224", CpuModel.Cpu224)]
    [InlineData("CPU 224XP", CpuModel.Cpu224XP)]
    [InlineData("cpu226", CpuModel.Cpu226)]
    [InlineData(" 221 ", CpuModel.Cpu221)]
    public void TryParse_TechnicianSpelling_FindsTheModel(string text, CpuModel model)
    {
        CpuModelNames.TryParse(text, out var parsed, out _).Should().BeTrue();
        parsed.Should().Be(model);
    }

    [Theory]
    [InlineData("214")]
    [InlineData("")]
    [InlineData(null)]
    [InlineData("CPU")]
    public void TryParse_UnknownModel_SaysWhichAreSupported(string? text)
    {
        CpuModelNames.TryParse(text, out _, out var error).Should().BeFalse();
        error.Should().Contain("supported: 221, 222, 224, 224XP, 226");
    }

    [Fact]
    public void All_EveryProfile_HasUniqueModelAndRevision()
    {
        CpuProfiles.All.Select(p => (p.Model, p.Revision)).Should().OnlyHaveUniqueItems();
        CpuProfiles.All.Should().HaveCount(8);
    }
}
