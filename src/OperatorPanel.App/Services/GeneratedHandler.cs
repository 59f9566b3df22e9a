using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.App.Services;

/// <summary>
/// Demo mode's <see cref="StlHandlerSource"/>: the handler StlGen generates for the station (the same text Generate PLC
/// code saves), so the demo line answers with the program the operator would load into the PLC.
/// </summary>
public static class GeneratedHandler
{
    public static bool TryGet(HandlerConfig config, SerialSettings serial, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(config);
        return HandlerGenerator.TryGenerateAwl(
            HandlerOptions.ForLine(config.Cpu, config.Port, config.Station.Address, config.WriteMask, config.ReplyDelayMs, serial), out awlText, out error);
    }
}
