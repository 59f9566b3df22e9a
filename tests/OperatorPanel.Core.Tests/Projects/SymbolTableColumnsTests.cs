using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

public sealed class SymbolTableColumnsTests
{
    [Theory]
    [InlineData("\t\tStart_PB\tI0.0\tgreen; on the door", new[] { "", "", "Start_PB", "I0.0", "green; on the door" })]
    [InlineData("Start_PB;I0.0;green, on the door", new[] { "Start_PB", "I0.0", "green, on the door" })]
    [InlineData("Start_PB,I0.0,green, on the door", new[] { "Start_PB", "I0.0", "green", "on the door" })]
    [InlineData("\"Start;PB\";I0.0;\"say \"\"go\"\"\"", new[] { "Start;PB", "I0.0", "say \"go\"" })]
    [InlineData("Start_PB I0.0", new[] { "Start_PB I0.0" })]
    public void Split_TabsFirstThenSemicolonsThenCommas_OutsideQuotes(string line, string[] columns)
    {
        SymbolTableColumns.Split(line).Should().Equal(columns);
    }

    [Fact]
    public void SymbolImport_SemicolonCsv_ReadsTheInputsAndOutputs()
    {
        var import = SymbolTableImport.Parse("Symbol;Address;Comment\r\nSens_Origen;I0.0;Sensor, homing\r\nMotor;Q0.1;\r\nSetpoint;VW100;not a bit\r\n");

        import.Inputs.Select(s => (s.Symbol, s.Address.ToString(), s.Description)).Should().Equal(("Sens_Origen", "I0.0", "Sensor, homing"));
        import.Outputs.Select(s => (s.Symbol, s.Address.ToString())).Should().Equal(("Motor", "Q0.1"));
        import.Rejected.Select(r => r.LineNumber).Should().Equal(4);
    }
}
