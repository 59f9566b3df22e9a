using OperatorPanel.Cli;

return OpanelApp.Run(args, Console.Out, Console.Error);
