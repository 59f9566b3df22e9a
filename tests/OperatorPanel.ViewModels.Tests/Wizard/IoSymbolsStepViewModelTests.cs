using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Wizard;

public sealed class IoSymbolsStepViewModelTests
{
    private const string MicroWinTable =
        "Symbol\tAddress\tComment\n"
        + "\t\tStart_Button\tI0.0\tGreen button, panel front\n"
        + "Stop_Button\tI0.1\tRed button\tExtra column\r\n"
        + "Motor\tQ0.0\t\"Conveyor \"\"main\"\" motor\"\n"
        + "Speed\tVW100\tLine speed\n"
        + "Flag\tM0.0\tInternal\n"
        + "\n"
        + "Just some text\n"
        + "Start_Again\tI0.0\tDuplicate\n"
        + "\tI0.2\tno symbol\n";

    [Fact]
    public void Paste_MicroWinSymbolTable_MergesIqBitsAndReportsRejectedLinesByNumber()
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        var step = wizard.IoStep;

        step.PasteCommand.Execute(MicroWinTable);

        step.Inputs.Should().HaveCount(14);
        step.Inputs[0].Should().BeEquivalentTo(new { Symbol = "Start_Button", Address = "I0.0", Description = "Green button, panel front" });
        step.Inputs[1].Should().BeEquivalentTo(new { Symbol = "Stop_Button", Address = "I0.1", Description = "Red button" });
        step.Outputs[0].Should().BeEquivalentTo(new { Symbol = "Motor", Address = "Q0.0", Description = "Conveyor \"main\" motor" });
        step.RejectedLines.Should().Equal(
            "line 5: VW100 is not an input or output bit; only I and Q bits such as I0.0 or Q1.7 are imported here",
            "line 6: M0.0 is not an input or output bit; only I and Q bits such as I0.0 or Q1.7 are imported here",
            "line 8: no address found; a line holds a symbol, an address such as I0.0 and a comment, separated by tabs (or by semicolons or commas)",
            "line 9: I0.0 is already on line 2",
            "line 10: I0.2 has no symbol before it");
        step.PasteReport.Should().Be("Pasted 2 inputs and 1 output; 5 lines rejected.");
    }

    [Fact]
    public void Paste_NewAddresses_AreAppendedAsRows()
    {
        var step = ProjectWizardViewModelTests.NewWizard().IoStep;

        step.Paste("Extra_In\tI2.0\tExpansion module input\nExtra_Out\tQ2.1\t");

        step.Inputs[^1].Should().BeEquivalentTo(new { Symbol = "Extra_In", Address = "I2.0", Description = "Expansion module input" });
        step.Outputs[^1].Should().BeEquivalentTo(new { Symbol = "Extra_Out", Address = "Q2.1", Description = "" });
        step.RejectedLines.Should().BeEmpty();
    }

    [Theory]
    [InlineData("Q0.0", "Input row 15 (Q0.0): an input is an I bit such as I0.0, not Q0.0.")]
    [InlineData("IB0", "Input row 15 (IB0): an input is an I bit such as I0.0, not IB0.")]
    [InlineData("I0.0", "Input row 15 (I0.0): I0.0 is listed twice.")]
    [InlineData("", "Input row 15 (no address): no address given.")]
    public void Next_BadInputRow_IsDisabledWithAMessageNamingTheRow(string address, string message)
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 1;

        wizard.IoStep.Inputs.Add(new IoSymbolRowViewModel("Extra", address));

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be(message);
        message.Should().EndWith($": {wizard.IoStep.Inputs[^1].Error}.", "the row shows the same reason as the step");
        wizard.IoStep.RemoveCommand.Execute(wizard.IoStep.Inputs[^1]);
        wizard.NextCommand.CanExecute(null).Should().BeTrue();
    }

    [Fact]
    public void Next_OutputSymbolSameAsAnInputsIgnoringCase_IsRefused()
    {
        var wizard = ProjectWizardViewModelTests.NewWizard();
        wizard.CurrentIndex = 1;

        wizard.IoStep.Outputs[0].Symbol = "INPUT_0_0";

        wizard.Message.Should().Be("Output row 1 (Q0.0): symbol 'INPUT_0_0' is used twice.");
    }
}
