using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Wizard;

/// <summary>Steps 3 and 4: addresses checked against the CPU chosen in step 1, with messages naming the row and value.</summary>
public sealed class StepValidationTests
{
    [Theory]
    [InlineData("VW8191", false, "Cell 1 (VW8191): VW8191 ends at VB8192, past the last V byte VB8191 of CPU 224.")]
    [InlineData("SMB5", true, "Cell 1 (SMB5): SMB5: SMB0-SMB29 are read-only system status bytes.")]
    [InlineData("IB0", true, "Cell 1 (IB0): IB0: inputs are read from the field; the panel never writes them.")]
    [InlineData("SB0", false, "Cell 1 (SB0): SB0: the Freeport link reads only I, Q, M and V: its handler leaves S bits out to stay small; copy the S bits to V in the PLC program (MOVB SB0, VB100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads S bits (choose PPI in step 5, Link).")]
    [InlineData("VW1O0", false, null)]
    public void MemoryCell_AddressRefused_NamesTheCellAndTheRule(string address, bool writable, string? message)
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 2;

        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Cell", address, DisplayFormat.Unsigned, writable));

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        if (message is null)
        {
            wizard.Message.Should().StartWith("Cell 1 (VW1O0): ");
        }
        else
        {
            wizard.Message.Should().Be(message);
        }
    }

    [Theory]
    [InlineData("AIW0", false, null)]
    [InlineData("AQW2", true, null)]
    [InlineData("T37", false, null)]
    [InlineData("C5", false, null)]
    [InlineData("SB0", true, null)]
    [InlineData("AIW0", true, "Cell 1 (AIW0): AIW0: analog inputs are read-only.")]
    [InlineData("T37", true, "Cell 1 (T37): T37: the panel reads timer current values but never writes them: no source says how a CPU takes that write over PPI, and the Freeport handler does not reach them.")]
    public void MemoryCell_PpiLink_AnalogTimerCounterAndSCellsAcceptedWhereThePpiLinkReachesThem(string address, bool writable, string? message)
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.LinkStep.Protocol = LinkProtocol.Ppi;
        wizard.CurrentIndex = 2;

        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Cell", address, DisplayFormat.Signed, writable));

        wizard.NextCommand.CanExecute(null).Should().Be(message is null, wizard.Message);
        if (message is not null)
        {
            wizard.Message.Should().Be(message);
        }
    }

    [Theory]
    [InlineData("VB110", "1..8", "", "", null)]
    [InlineData("VB110", "1..300", "", "", "Cell 1 (VB110): VB110: 300 is outside 0..255, the range of an unsigned byte (a signed byte takes -128..127).")]
    [InlineData("VB110", "8..1", "", "", "Cell 1 (VB110): the range 8..1 ends below its start.")]
    [InlineData("VW150", "", "0..1000 -> 0..100", "%", null)]
    [InlineData("VW150", "", "0..1000", "%", "Cell 1 (VW150): '0..1000' is not a scale; write it as raw low..high -> value low..high, e.g. 0..1000 -> 0..100.")]
    public void MemoryCell_RangeScaleAndUnit_CheckedAsTheProjectFileChecksThem(string address, string range, string scale, string unit, string? message)
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 2;

        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Cell", address, DisplayFormat.Unsigned, writable: true) { Range = range, Scale = scale, Unit = unit });

        wizard.NextCommand.CanExecute(null).Should().Be(message is null, wizard.Message);
        if (message is not null)
        {
            wizard.Message.Should().Be(message);
        }
    }

    [Fact]
    public void MemoryCell_AddressChangedToAWord_FormatFallsBackFromBool()
    {
        var row = new MemoryCellRowViewModel("Cell", "M0.0", DisplayFormat.Bool);

        row.Address = "MW0";

        row.Format.Should().Be(DisplayFormat.Unsigned);
        row.FittingFormats.Should().NotContain(DisplayFormat.Bool);
    }

    [Fact]
    public void MemoryCell_FloatOnAWord_IsRefused()
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 2;
        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Cell", "VW0", DisplayFormat.Float));

        wizard.Message.Should().Be("Cell 1 (VW0): Float cannot show VW0.");
    }

    [Theory]
    [InlineData("Q0.0", "Alarm 1 (Q0.0): an alarm flag is an M or V bit such as M2.0 or V100.3, not Q0.0.")]
    [InlineData("MB0", "Alarm 1 (MB0): an alarm flag is an M or V bit such as M2.0 or V100.3, not MB0.")]
    [InlineData("M32.0", "Alarm 1 (M32.0): M32.0 is past the last M byte MB31 of CPU 221.")]
    public void AlarmFlag_NotAnMOrVBitOfTheCpu_IsRefused(string flag, string message)
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CpuStep.Cpu = CpuProfiles.For(CpuModel.Cpu221);
        wizard.CurrentIndex = 3;

        wizard.AlarmStep.Alarms.Add(new AlarmTextRowViewModel(flag, "Jam"));

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be(message);
    }

    [Fact]
    public void AlarmFlag_UsedTwice_IsRefusedAtTheSecond()
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 3;
        wizard.AlarmStep.Alarms.Add(new AlarmTextRowViewModel("V100.0", "Jam"));

        wizard.AlarmStep.AddCommand.Execute(null);
        wizard.AlarmStep.Alarms[1].Flag = "v100.0";
        wizard.AlarmStep.Alarms[1].Text = "Again";

        wizard.Message.Should().Be("Alarm 2 (v100.0): V100.0 already has an alarm.");
    }
}
