using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Link;

/// <summary>The CLI's <see cref="StlHandlerSource"/>: the handler StlGen generates for the station's settings.</summary>
internal static class GeneratedHandler
{
    public static bool TryGet(HandlerConfig config, SerialSettings serial, [NotNullWhen(true)] out string? awlText, [NotNullWhen(false)] out string? error)
    {
        ArgumentNullException.ThrowIfNull(config);
        return HandlerGenerator.TryGenerateAwl(
            HandlerOptions.ForLine(config.Cpu, config.Port, config.Station.Address, config.WriteMask, config.ReplyDelayMs, serial), out awlText, out error);
    }
}
