using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

/// <summary>Password-protected POUs as Micro/WIN exports them (one network titled "This POU is password-protected ..."): warned about, merged.</summary>
public sealed class HandlerMergerProtectedTests
{
    /// <summary>OB1 calls SBR7 (line 5); the protected block starts at line 7.</summary>
    private static string Program(string name) => UserProgram.WithBlocks(
        ["LD     SM0.1", "CALL   SBR7, 1"],
        [$"SUBROUTINE_BLOCK {name}:SBR7", "VAR_INPUT", "Mode:BYTE;", "END_VAR", "BEGIN", "Network 1 // This POU is password-protected against editing and viewing.", "", "END_SUBROUTINE_BLOCK"]);

    private static HandlerOptions Cpu226OnPort(int port) => UserProgram.Cpu226 with { Port = port };

    [Fact]
    public void Merge_ProtectedBlockAsExported_WarnsNamingItAndWhatCannotBeChecked()
    {
        var result = HandlerMerger.Merge(Program("MOTOR_CTRL"), UserProgram.Cpu224);

        result.Ok.Should().BeTrue();
        result.MergedText.Should().Contain("SUBROUTINE_BLOCK MOTOR_CTRL:SBR7");
        var warning = result.Warnings.Should().ContainSingle().Which;
        warning.Should().Match<MergeDiagnostic>(d => d.Id == StlDiagnostics.UserBlockWithoutBody && d.Line == 7);
        warning.Message.Should().Be("MOTOR_CTRL (SBR7, line 7) is password-protected: the export holds none of its code, so the handler's port 0, interrupt events 23, 10, 9 and VB7764-VB8191 cannot be checked against it; check them yourself, or export it unprotected");
    }

    [Theory]
    [InlineData("MBUS_INIT")]
    [InlineData("MBUS_SLAVE")]
    public void Merge_ProtectedModbusSlaveOnHandlersPort_WarnsThatTheLibraryTakesPort0(string name)
    {
        var result = HandlerMerger.Merge(Program(name), Cpu226OnPort(0));

        result.Ok.Should().BeTrue();
        result.Warnings.Select(w => w.Id).Should().Equal(StlDiagnostics.UserBlockWithoutBody, StlDiagnostics.LibraryTakesHandlerPort);
        result.Warnings.Last().Message.Should().StartWith($"{name} (SBR7) is a block of the Modbus RTU slave library, which runs Freeport on port 0, the handler's port: both would set up SMB30 and receive on the port; put the handler on port 1 with --plc-port 1");
    }

    [Fact]
    public void Merge_ProtectedModbusSlaveOnOnePortCpu_SaysBothCannotRun()
    {
        var result = HandlerMerger.Merge(Program("MBUS_INIT"), UserProgram.Cpu224);

        result.Warnings.Last().Message.Should().Contain("the CPU has one port: the two cannot run together");
    }

    [Fact]
    public void Merge_ProtectedModbusSlaveWithHandlerOnPort1_OnlyTheUncheckedWarning()
    {
        var result = HandlerMerger.Merge(Program("MBUS_INIT"), Cpu226OnPort(1));

        result.Warnings.Should().ContainSingle().Which.Id.Should().Be(StlDiagnostics.UserBlockWithoutBody);
    }
}
