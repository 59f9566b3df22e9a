using System.CommandLine;
using OperatorPanel.Simulator.Hosting;

namespace OperatorPanel.Cli.Link;

/// <summary><c>--model stl|reference</c>, shared by simulate and every --demo verb.</summary>
internal static class ModelOption
{
    public static Option<SimulationModel> Create() => new("--model")
    {
        Description = "Simulated PLC: stl = the generated handler .awl in the STL interpreter (default), reference = the plain C# model",
        DefaultValueFactory = _ => SimulationModel.Stl,
    };
}
